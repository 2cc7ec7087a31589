// BVH reader. The file is split into lines first so that every message can name a line and
// so the frame count can be checked against what is really there before anything is
// allocated for it. The hierarchy is read as a token stream (BVH writers differ in how they
// wrap lines there); each MOTION frame must be exactly one line.
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "anim/bvh.h"
#include "anim/bvh_channels.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/log.h"

namespace throng::anim {
namespace {

constexpr int kMaxJoints = 1024;

struct Line {
  std::string_view text;
  int number = 0;  // 1-based
};

// "\r\n", "\n" and a lone "\r" all end a line, so mixed endings number lines the way an
// editor shows them.
std::vector<Line> splitLines(std::string_view text) {
  std::vector<Line> lines;
  size_t start = 0;
  int number = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n' && text[i] != '\r') continue;
    lines.push_back({text.substr(start, i - start), number++});
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
  }
  if (start < text.size() || lines.empty()) lines.push_back({text.substr(start), number});
  return lines;
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

bool isBlank(std::string_view s) {
  for (char c : s) {
    if (!isSpace(c)) return false;
  }
  return true;
}

// Tokens of one line, appended to `out`.
void splitTokens(std::string_view line, std::vector<std::string_view>& out) {
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

// A token as it may appear in a message: binary junk must not garble the terminal.
std::string quoted(std::string_view token) {
  constexpr size_t kMaxShown = 40;
  std::string out = "'";
  for (size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    out += (c >= 0x20 && c < 0x7f) ? char(c) : '?';
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

enum class NumberStatus { Ok, NotANumber, NotFinite };

NumberStatus parseFloat(std::string_view s, float& value) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);  // from_chars rejects a leading '+'
  if (s.empty() || s[0] == '+') return NumberStatus::NotANumber;
  double d = 0.0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), d);
  if (end != s.data() + s.size()) return NumberStatus::NotANumber;
  if (ec == std::errc::result_out_of_range) {
    // Too large is an error; too small (1e-400) is just zero.
    d = std::strtod(std::string(s).c_str(), nullptr);
    if (!std::isfinite(d) || std::fabs(d) >= 1.0) return NumberStatus::NotFinite;
  } else if (ec != std::errc()) {
    return NumberStatus::NotANumber;
  }
  if (!std::isfinite(d) || std::fabs(d) > std::numeric_limits<float>::max()) {
    return NumberStatus::NotFinite;
  }
  value = static_cast<float>(d);
  return NumberStatus::Ok;
}

bool parseInt(std::string_view s, long long& value) {
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

struct Token {
  std::string_view text;
  int line = 0;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& source)
      : source_(source), lines_(splitLines(text)) {}

  RawClip parse() {
    RawClip clip;
    clip.sourceName = source_;
    expectKeyword("HIERARCHY");
    Token root = next("ROOT");
    if (root.text != "ROOT") failAt(root.line, "expected ROOT, found ", quoted(root.text));
    parseHierarchy(root.line, clip.skeleton);
    for (const Joint& j : clip.skeleton.joints) clip.channelCount += int(j.channels.size());
    parseMotion(clip);
    return clip;
  }

 private:
  template <typename... Args>
  [[noreturn]] void failAt(int line, const Args&... args) const {
    fail(source_, ":", line, ": ", args...);
  }

  int lastLine() const { return lines_.back().number; }

  // Moves to the next token, crossing line ends; false at the end of the text.
  bool skipToToken() {
    while (lineIndex_ < lines_.size()) {
      std::string_view text = lines_[lineIndex_].text;
      while (column_ < text.size() && isSpace(text[column_])) ++column_;
      if (column_ < text.size()) return true;
      ++lineIndex_;
      column_ = 0;
    }
    return false;
  }

  Token take() {
    const Line& line = lines_[lineIndex_];
    size_t start = column_;
    while (column_ < line.text.size() && !isSpace(line.text[column_])) ++column_;
    return {line.text.substr(start, column_ - start), line.number};
  }

  Token next(std::string_view expected) {
    if (!skipToToken()) failAt(lastLine(), "unexpected end of file, expected ", expected);
    return take();
  }

  // The next token, which must be on `line` (a joint's name, the frame count).
  Token nextOnLine(int line, std::string_view expected) {
    if (!skipToToken() || lines_[lineIndex_].number != line) {
      failAt(line, "expected ", expected, " at the end of the line");
    }
    return take();
  }

  void expectKeyword(std::string_view keyword) {
    Token t = next(keyword);
    if (t.text != keyword) failAt(t.line, "expected ", keyword, ", found ", quoted(t.text));
  }

  float nextNumber(std::string_view what) {
    Token t = next(what);
    float value = 0.0f;
    switch (parseFloat(t.text, value)) {
      case NumberStatus::Ok:
        return value;
      case NumberStatus::NotFinite:
        failAt(t.line, "expected a finite number for ", what, ", found ", quoted(t.text));
      case NumberStatus::NotANumber:
        failAt(t.line, "expected a number for ", what, ", found ", quoted(t.text));
    }
    return value;
  }

  glm::vec3 parseOffset() {
    expectKeyword("OFFSET");
    glm::vec3 offset;
    for (int i = 0; i < 3; ++i) offset[i] = nextNumber("OFFSET");
    return offset;
  }

  std::vector<Channel> parseChannels() {
    expectKeyword("CHANNELS");
    Token countToken = next("a channel count");
    long long count = 0;
    if (!parseInt(countToken.text, count) || (count != 3 && count != 6)) {
      failAt(countToken.line, "expected a channel count of 3 or 6, found ",
             quoted(countToken.text));
    }
    std::vector<Channel> channels;
    bool seen[6] = {};
    for (long long i = 0; i < count; ++i) {
      Token t = next("a channel name");
      std::optional<Channel> channel = parseChannelName(t.text);
      if (!channel) {
        failAt(t.line, "unknown channel ", quoted(t.text), ", expected Xposition, Yposition, ",
               "Zposition, Xrotation, Yrotation or Zrotation");
      }
      if (seen[int(*channel)]) failAt(t.line, "channel ", quoted(t.text), " listed twice");
      if (count == 3 && !isRotation(*channel)) {
        failAt(t.line, "expected Xrotation, Yrotation and Zrotation on a 3-channel joint, found ",
               quoted(t.text));
      }
      seen[int(*channel)] = true;
      channels.push_back(*channel);
    }
    return channels;
  }

  // ROOT/JOINT name { OFFSET CHANNELS (JOINT ... | End Site { OFFSET })* }, without
  // recursion so that nesting depth cannot exhaust the stack.
  void parseHierarchy(int rootLine, Skeleton& skeleton) {
    std::vector<int> open;  // joints whose '}' is still to come
    auto beginJoint = [&](int parent, int line) {
      Token name = nextOnLine(line, "a joint name");
      if (name.text == "{") failAt(line, "expected a joint name, found '{'");
      if (skeleton.jointCount() >= kMaxJoints) {
        failAt(line, "more than ", kMaxJoints, " joints (expected at most ", kMaxJoints, ")");
      }
      Joint joint;
      joint.name = std::string(name.text);
      joint.parent = parent;
      expectKeyword("{");
      joint.offset = parseOffset();
      joint.channels = parseChannels();
      open.push_back(skeleton.jointCount());
      skeleton.joints.push_back(std::move(joint));
    };
    beginJoint(-1, rootLine);
    while (!open.empty()) {
      Joint& current = skeleton.joints[size_t(open.back())];
      std::string expected = concat("JOINT, End Site or '}' closing joint '", current.name, "'");
      Token t = next(expected);
      if (t.text == "JOINT") {
        beginJoint(open.back(), t.line);
      } else if (t.text == "End") {
        Token site = nextOnLine(t.line, "'Site' after 'End'");
        if (site.text != "Site") failAt(t.line, "expected 'End Site', found 'End ", site.text, "'");
        if (current.endSite) failAt(t.line, "second End Site in joint '", current.name, "'");
        expectKeyword("{");
        glm::vec3 offset = parseOffset();
        Token close = next("'}' closing the End Site");
        if (close.text != "}") {
          failAt(close.line, "expected '}' closing the End Site, found ", quoted(close.text));
        }
        current.endSite = offset;
      } else if (t.text == "}") {
        open.pop_back();
      } else {
        failAt(t.line, "unknown token ", quoted(t.text), ", expected ", expected);
      }
    }
  }

  // "Frames:" or "Frames :" (both occur in the wild).
  Token expectLabel(std::string_view word, std::string_view expected) {
    Token t = next(expected);
    if (t.text == concat(word, ":")) return t;
    if (t.text == word) {
      Token colon = next("':'");
      if (colon.text == ":") return t;
    }
    failAt(t.line, "expected ", expected, ", found ", quoted(t.text));
  }

  void parseMotion(RawClip& clip) {
    if (!skipToToken()) failAt(lastLine(), "expected a MOTION section, found end of file");
    Token motion = take();
    if (motion.text == "ROOT") failAt(motion.line, "expected MOTION (only one ROOT is supported)");
    if (motion.text != "MOTION")
      failAt(motion.line, "expected MOTION, found ", quoted(motion.text));
    Token frames = expectLabel("Frames", "'Frames:'");
    Token countToken = nextOnLine(frames.line, "a frame count");
    long long frameCount = 0;
    if (!parseInt(countToken.text, frameCount) || frameCount < 1) {
      failAt(frames.line, "expected a frame count of at least 1, found ", quoted(countToken.text));
    }
    Token frameWord = next("'Frame Time:'");
    if (frameWord.text != "Frame") {
      failAt(frameWord.line, "expected 'Frame Time:', found ", quoted(frameWord.text));
    }
    Token timeLabel = expectLabel("Time", "'Frame Time:'");
    Token timeToken = nextOnLine(timeLabel.line, "a frame time");
    float frameTime = 0.0f;
    if (parseFloat(timeToken.text, frameTime) != NumberStatus::Ok || !(frameTime > 0.0f)) {
      failAt(timeToken.line, "expected a positive frame time in seconds, found ",
             quoted(timeToken.text));
    }
    size_t first = lineIndex_ + 1;
    if (skipToToken() && lineIndex_ < first) {
      failAt(timeToken.line, "unexpected ", quoted(take().text), " after the frame time");
    }
    readFrames(clip, first, frameCount, frames.line);
    clip.frameTime = frameTime;
  }

  void readFrames(RawClip& clip, size_t first, long long frameCount, int framesLine) {
    // Validate the declared size against what the file really holds before reserving.
    long long available = 0;
    size_t bytes = 0;
    for (size_t i = first; i < lines_.size(); ++i) {
      if (!isBlank(lines_[i].text)) ++available;
      bytes += lines_[i].text.size() + 1;
    }
    if (frameCount > available || frameCount > std::numeric_limits<int>::max()) {
      // Named at the line where the data runs out: that is where the file was cut.
      failAt(lastDataLine(first), "the motion data ends after ", available, " of the ", frameCount,
             " frames that Frames: on line ", framesLine, " declares (truncated file?)");
    }
    // Each value needs at least one character and a separator.
    const long long channels = clip.channelCount;
    if (frameCount * channels > (long long)(bytes / 2) + frameCount) {
      failAt(framesLine, "Frames: ", frameCount, " with ", channels,
             " channels needs more values than the file holds (truncated file?)");
    }
    clip.frameCount = int(frameCount);
    clip.values.reserve(size_t(frameCount * channels));
    std::vector<std::string_view> tokens;
    long long frame = 0;
    size_t i = first;
    for (; i < lines_.size() && frame < frameCount; ++i) {
      if (isBlank(lines_[i].text)) continue;
      tokens.clear();
      splitTokens(lines_[i].text, tokens);
      const int line = lines_[i].number;
      if ((long long)tokens.size() != channels) {
        failAt(line, "expected ", channels, " values on frame ", frame + 1, " of ", frameCount,
               ", found ", tokens.size());
      }
      for (std::string_view token : tokens) {
        float value = 0.0f;
        NumberStatus status = parseFloat(token, value);
        if (status == NumberStatus::NotFinite) {
          failAt(line, "expected a finite number on frame ", frame + 1, ", found ", quoted(token));
        }
        if (status == NumberStatus::NotANumber) {
          failAt(line, "expected a number on frame ", frame + 1, ", found ", quoted(token));
        }
        clip.values.push_back(value);
      }
      ++frame;
    }
    // More motion lines than declared (assimp's Boxing_Toes.bvh: 3,070 under Frames: 3069):
    // other readers load such files, so the declared frames are kept and the rest ignored.
    const long long extra = available - frameCount;
    if (extra > 0) {
      for (; i < lines_.size() && isBlank(lines_[i].text); ++i) {
      }
      warnings_.push_back(concat(source_, ":", lines_[i].number, ": ", extra, " motion line",
                                 extra == 1 ? "" : "s", " after the ", frameCount,
                                 " frames that Frames: on line ", framesLine,
                                 " declares; using the declared frames"));
    }
  }

  // Number of the last non-blank line from index `first` on (the last line when all are blank).
  int lastDataLine(size_t first) const {
    for (size_t i = lines_.size(); i > first; --i)
      if (!isBlank(lines_[i - 1].text)) return lines_[i - 1].number;
    return first > 0 ? lines_[first - 1].number : lastLine();
  }

 public:
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  const std::string& source_;
  std::vector<Line> lines_;
  size_t lineIndex_ = 0;
  size_t column_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace

RawClip parseBvh(std::string_view text, const std::string& sourceName,
                 std::vector<std::string>* warnings) {
  Parser parser(text, sourceName);
  RawClip clip = parser.parse();
  for (const std::string& w : parser.warnings()) {
    if (warnings)
      warnings->push_back(w);
    else
      logWarning(w);
  }
  return clip;
}

RawClip loadBvh(const std::filesystem::path& path) {
  return parseBvh(readTextFile(path), path.string());
}

}  // namespace throng::anim
