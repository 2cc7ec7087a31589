#pragma once
// BVH channel names, shared by the parser and the `clip info` command.
#include <optional>
#include <string_view>

#include "anim/skeleton.h"

namespace throng::anim {

inline std::string_view channelName(Channel channel) {
  switch (channel) {
    case Channel::Xposition: return "Xposition";
    case Channel::Yposition: return "Yposition";
    case Channel::Zposition: return "Zposition";
    case Channel::Xrotation: return "Xrotation";
    case Channel::Yrotation: return "Yrotation";
    case Channel::Zrotation: return "Zrotation";
  }
  return "?";
}

// Exact, case-sensitive names as every BVH writer spells them.
inline std::optional<Channel> parseChannelName(std::string_view name) {
  for (Channel c : {Channel::Xposition, Channel::Yposition, Channel::Zposition,
                    Channel::Xrotation, Channel::Yrotation, Channel::Zrotation}) {
    if (channelName(c) == name) return c;
  }
  return std::nullopt;
}

inline bool isRotation(Channel channel) {
  return channel == Channel::Xrotation || channel == Channel::Yrotation ||
         channel == Channel::Zrotation;
}

// 0, 1, 2 for the X, Y, Z channel of either kind.
inline int channelAxis(Channel channel) {
  switch (channel) {
    case Channel::Xposition: case Channel::Xrotation: return 0;
    case Channel::Yposition: case Channel::Yrotation: return 1;
    case Channel::Zposition: case Channel::Zrotation: return 2;
  }
  return 0;
}

}  // namespace throng::anim
