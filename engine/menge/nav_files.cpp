// Menge's whitespace-separated text resources: navigation meshes (.nav) and road maps. Counts
// are checked against the bytes left in the file before anything is reserved, and every index
// against what it indexes.
#include <charconv>
#include <cmath>
#include <unordered_set>

#include "core/error.h"
#include "menge/menge.h"
#include "menge/read_file.h"

namespace throng::menge {

namespace {

class Tokens {
 public:
  Tokens(std::string_view text, const std::filesystem::path& source)
      : text_(text), source_(source.string()) {}

  bool atEnd() {
    skipSpace();
    return pos_ >= text_.size();
  }
  int line() const { return line_; }
  // The line of the next token (after the whitespace before it).
  int nextLine() {
    skipSpace();
    return line_;
  }

  template <typename... Args>
  [[noreturn]] void fail(const Args&... args) const {
    throng::fail(source_, ":", line_, ": ", args...);
  }

  std::string_view next(std::string_view what) {
    if (atEnd()) fail("expected ", what, ", found the end of the file");
    const size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_])) ++pos_;
    return text_.substr(start, pos_ - start);
  }

  float number(std::string_view what) {
    const std::string_view token = next(what);
    float value = 0.0f;
    const char* begin = token.data() + (token.starts_with('+') ? 1 : 0);
    const auto [end, ec] = std::from_chars(begin, token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value)) {
      fail("expected ", what, " (a finite number), got \"", token, "\"");
    }
    return value;
  }

  int64_t integer(std::string_view what) {
    const std::string_view token = next(what);
    int64_t value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size()) {
      fail("expected ", what, " (an integer), got \"", token, "\"");
    }
    return value;
  }

  // An index in [0, size).
  uint32_t index(std::string_view what, size_t size) {
    const int64_t value = integer(what);
    if (value < 0 || static_cast<uint64_t>(value) >= size) {
      fail("expected ", what, " in [0, ", size, "), got ", value);
    }
    return static_cast<uint32_t>(value);
  }

  // A count of items that take at least `tokensEach` tokens: each token and its separator take
  // two bytes or more, so a count beyond what the rest of the file can hold is refused before
  // anything is allocated for it.
  size_t count(std::string_view what, size_t tokensEach) {
    const int64_t value = integer(what);
    if (value < 0) fail("expected ", what, " >= 0, got ", value);
    const uint64_t room = (text_.size() - pos_ + 1) / (2 * tokensEach);
    if (static_cast<uint64_t>(value) > room) {
      fail("expected ", what, " that the rest of the file can hold (at most ", room, "), got ",
           value);
    }
    return static_cast<size_t>(value);
  }

 private:
  static bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  }
  void skipSpace() {
    while (pos_ < text_.size() && isSpace(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::string source_;
  size_t pos_ = 0;
  int line_ = 1;
};

// Where each record started, for messages about cross-references checked after reading.
struct NavLines {
  std::vector<int> edges, obstacles, nodes;
};

// Per node: centre (2), polygon count + 3 vertices, plane (3), edge and obstacle counts.
constexpr size_t kNodeMinTokens = 2 + 4 + 3 + 2;

void readNavHeader(Tokens& in, NavMesh& mesh, NavLines& lines) {
  mesh.vertices.resize(in.count("the vertex count", 2));
  for (glm::vec2& v : mesh.vertices) v = {in.number("a vertex x"), in.number("a vertex y")};
  mesh.edges.resize(in.count("the edge count", 4));
  lines.edges.reserve(mesh.edges.size());
  const size_t vertexCount = mesh.vertices.size();
  for (NavMesh::Edge& e : mesh.edges) {
    lines.edges.push_back(in.nextLine());
    e.v0 = in.index("an edge's first vertex", vertexCount);
    e.v1 = in.index("an edge's second vertex", vertexCount);
    // Nodes are read later: their range is checked once all are known.
    e.node0 = in.index("an edge's first node", UINT32_MAX);
    e.node1 = in.index("an edge's second node", UINT32_MAX);
  }
  mesh.obstacles.resize(in.count("the obstacle count", 4));
  lines.obstacles.reserve(mesh.obstacles.size());
  for (NavMesh::Obstacle& o : mesh.obstacles) {
    lines.obstacles.push_back(in.nextLine());
    o.v0 = in.index("an obstacle's first vertex", vertexCount);
    o.v1 = in.index("an obstacle's second vertex", vertexCount);
    o.node = in.index("an obstacle's node", UINT32_MAX);
    const int64_t next = in.integer("an obstacle's next obstacle");
    if (next < -1 || next >= static_cast<int64_t>(mesh.obstacles.size())) {
      in.fail("expected an obstacle's next obstacle in [-1, ", mesh.obstacles.size(), "), got ",
              next);
    }
    o.next = static_cast<int32_t>(next);
  }
}

void readIndexList(Tokens& in, std::vector<uint32_t>& out, std::string_view what, size_t size) {
  out.resize(in.count(what, 1));
  for (uint32_t& i : out) i = in.index(what, size);
}

void readNavNode(Tokens& in, NavMesh& mesh, NavMesh::Node& node) {
  node.center = {in.number("a node's centre x"), in.number("a node's centre y")};
  readIndexList(in, node.polygon, "a node polygon's vertex", mesh.vertices.size());
  if (node.polygon.size() < 3) in.fail("expected a node polygon of at least 3 vertices");
  node.plane = {in.number("a node's plane a"), in.number("a node's plane b"),
                in.number("a node's plane c")};
  readIndexList(in, node.edges, "a node's edge", mesh.edges.size());
  readIndexList(in, node.obstacles, "a node's obstacle", mesh.obstacles.size());
}

void readNavGroups(Tokens& in, NavMesh& mesh, NavLines& lines) {
  std::unordered_set<std::string> names;
  while (!in.atEnd()) {
    NavMesh::Group group;
    group.name = std::string(in.next("a node group name"));
    if (!names.insert(group.name).second) in.fail("node group '", group.name, "' defined twice");
    group.firstNode = static_cast<uint32_t>(mesh.nodes.size());
    group.nodeCount = static_cast<uint32_t>(in.count("the group's node count", kNodeMinTokens));
    mesh.nodes.resize(mesh.nodes.size() + group.nodeCount);
    for (uint32_t n = 0; n < group.nodeCount; ++n) {
      NavMesh::Node& node = mesh.nodes[group.firstNode + n];
      node.group = static_cast<uint32_t>(mesh.groups.size());
      lines.nodes.push_back(in.nextLine());
      readNavNode(in, mesh, node);
    }
    mesh.groups.push_back(std::move(group));
  }
  if (mesh.nodes.empty()) in.fail("expected at least one node group with nodes");
}

// Node references in edges and obstacles, and each node's neighbours across its edges.
void linkNavMesh(NavMesh& mesh, const NavLines& lines, const std::string& source) {
  const size_t nodeCount = mesh.nodes.size();
  for (size_t e = 0; e < mesh.edges.size(); ++e) {
    const NavMesh::Edge& edge = mesh.edges[e];
    if (edge.node0 >= nodeCount || edge.node1 >= nodeCount) {
      fail(source, ":", lines.edges[e], ": edge ", e, " names node ",
           std::max(edge.node0, edge.node1), ", expected a node index < ", nodeCount);
    }
  }
  for (size_t o = 0; o < mesh.obstacles.size(); ++o) {
    if (mesh.obstacles[o].node >= nodeCount) {
      fail(source, ":", lines.obstacles[o], ": obstacle ", o, " names node ",
           mesh.obstacles[o].node, ", expected a node index < ", nodeCount);
    }
  }
  for (size_t n = 0; n < nodeCount; ++n) {
    NavMesh::Node& node = mesh.nodes[n];
    node.neighbors.reserve(node.edges.size());
    for (const uint32_t e : node.edges) {
      const NavMesh::Edge& edge = mesh.edges[e];
      if (edge.node0 != n && edge.node1 != n) {
        fail(source, ":", lines.nodes[n], ": node ", n, " lists edge ", e,
             ", expected an edge touching it (it joins nodes ", edge.node0, " and ", edge.node1,
             ")");
      }
      node.neighbors.push_back(edge.node0 == n ? edge.node1 : edge.node0);
    }
  }
}

}  // namespace

NavMesh parseNavMesh(std::string_view text, const std::filesystem::path& source) {
  NavMesh mesh;
  mesh.source = source;
  Tokens in(text, source);
  NavLines lines;
  readNavHeader(in, mesh, lines);
  readNavGroups(in, mesh, lines);
  linkNavMesh(mesh, lines, source.string());
  return mesh;
}

RoadMap parseRoadMap(std::string_view text, const std::filesystem::path& source) {
  RoadMap map;
  map.source = source;
  Tokens in(text, source);
  const size_t vertexCount = in.count("the vertex count", 3);
  map.vertices.resize(vertexCount);
  std::vector<int64_t> degree(vertexCount);
  std::vector<int> lines(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v) {
    degree[v] = in.integer("a vertex degree");
    if (degree[v] < 0 || degree[v] > INT32_MAX) in.fail("expected a vertex degree >= 0");
    lines[v] = in.line();
    map.vertices[v] = {in.number("a vertex x"), in.number("a vertex y")};
  }
  map.edges.resize(in.count("the edge count", 2));
  for (auto& [from, to] : map.edges) {
    from = in.index("an edge's first vertex", vertexCount);
    to = in.index("an edge's second vertex", vertexCount);
    --degree[from];
    --degree[to];
  }
  if (!in.atEnd()) in.fail("expected the end of the file after the edges");
  for (size_t v = 0; v < vertexCount; ++v) {
    if (degree[v] != 0) {
      fail(source.string(), ":", lines[v], ": vertex ", v,
           "'s degree does not match the edges naming it (off by ", degree[v], ")");
    }
  }
  return map;
}

NavMesh readNavMesh(const std::filesystem::path& navFile) {
  return parseNavMesh(detail::readBoundedFile(navFile), navFile);
}

RoadMap readRoadMap(const std::filesystem::path& roadMapFile) {
  return parseRoadMap(detail::readBoundedFile(roadMapFile), roadMapFile);
}

}  // namespace throng::menge
