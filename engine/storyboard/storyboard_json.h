#pragma once
// The JSON form printed by `throng storyboard decode --json` and read by `encode`:
// {"schema":"throng.storyboard","version":1,"width":W,"height":H,"agents":[{"x":..,"y":..,"heading":"Down","state":"hurried",
//  "action":"walk","group":G},...],"invalid":[{"x":..,"y":..,"reason":"..."}]}
#include <string>
#include <string_view>

#include "storyboard/codec.h"

namespace throng::storyboard {

std::string storyboardToJson(const Storyboard& storyboard);
// Reads width, height and agents ("invalid" is ignored; "schema" and "version" may be absent,
// as in files written before they were added); throws Error naming `source`.
Storyboard storyboardFromJson(std::string_view text, const std::string& source);

}  // namespace throng::storyboard
