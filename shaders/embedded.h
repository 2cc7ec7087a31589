#pragma once
// SPIR-V compiled from shaders/*.comp|vert|frag at build time (see cmake/Shaders.cmake).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace throng::shaders {
// Empty span when no shader of that file name was built.
std::span<const uint32_t> embeddedSpirv(std::string_view name);
std::vector<std::string_view> embeddedShaderNames();
}  // namespace throng::shaders
