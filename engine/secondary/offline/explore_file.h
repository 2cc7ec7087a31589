#pragma once
// The .tsg file: everything an exploration needs to be inspected, compressed or resumed —
// the run config (garment and exploration options), the primary graph, the cloth mesh, the
// secondary graph (states, edges, merge errors), every cloth frame (positions + velocities),
// the merge queue, counters and the error history, and (from version 2) the identity of the
// skeleton and clip pair the run graph was built from. binary_io chunks (magic "THRNGTSG"),
// written atomically, so the file on disk is always a complete graph. Version 1 files are read as
// made for the built-in run (the only pair `cloth explore` knew then).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/binary_io.h"
#include "secondary/clip_identity.h"
#include "secondary/offline/secondary_graph.h"

namespace throng::secondary {

constexpr std::string_view kTsgMagic = "THRNGTSG";
constexpr uint32_t kTsgVersion = 2;

struct ExploreFile {
  nlohmann::json
      config;  // {"garment": {...}, "explore": {"depth", "max_states", "velocity_scale"}}
  PrimaryGraph primary;
  ClothMesh mesh;
  SecondaryGraph graph;
  ClipPairIdentity clips;  // always recorded after loading
};

// Mesh chunks (tags 'M…'), for any file that embeds a garment.
void addClothMeshChunks(ChunkWriter& writer, const ClothMesh& mesh);
ClothMesh readClothMeshChunks(const ChunkReader& reader);
// Secondary graph chunks (tags 'S…'); the frames are borrowed: `graph` must outlive the write.
void addSecondaryGraphChunks(ChunkWriter& writer, const SecondaryGraph& graph);
SecondaryGraph readSecondaryGraphChunks(const ChunkReader& reader, const PrimaryGraph& primary);

void saveExploreFile(const std::filesystem::path& path, const nlohmann::json& config,
                     const PrimaryGraph& primary, const ClothMesh& mesh,
                     const SecondaryGraph& graph, const ClipPairIdentity& clips);
// Throws Error naming the file on a bad magic, version, size, checksum or an inconsistent graph.
ExploreFile loadExploreFile(const std::filesystem::path& path);
// `throng cloth info` for a .tsg: counts, largest merge error, bytes; reads no frame.
nlohmann::json exploreFileInfo(const std::filesystem::path& path, bool withHistory = false);

}  // namespace throng::secondary
