#pragma once
// Small text helpers shared by the parsers and the device picker.
#include <cctype>
#include <string>

namespace throng {

// ASCII lower case (names in BVH files, device names); other bytes unchanged.
inline std::string toLower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace throng
