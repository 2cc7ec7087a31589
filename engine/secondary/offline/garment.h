#pragma once
// The garments the exploration knows, built from a JSON config so that a resumed run and every
// MPI rank rebuild exactly the same simulator: "toy" (toy_garment.h, for tests and quick runs)
// and "cape" (the XPBD cape of cloth_sim.h on the crowd's run graph).
//
// Config (every field optional but "name"; defaultGarmentConfig fills them in):
//   {"name": "cape", "seed": 1, "initial_node": 0, "velocity_jitter": 0.01, "shoulder_weight":
//   0.05, "slow": "", "fast": "" (BVH files of the run pair; empty: the built-in run),
//    "cape": {"columns": 32, "rows": 48, "bucket_width": 0.05, "substeps": 10, "iterations": 1,
//             "settle_frames": 60, "internal_damping": 150},
//    "toy": {"links": 6, "link_length": 0.08, "substeps": 4, "drag": 10}}
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "secondary/clip_identity.h"
#include "secondary/offline/merge_metric.h"
#include "secondary/secondary_types.h"

namespace throng::secondary {

struct Garment {
  nlohmann::json config;  // complete, with defaults
  std::shared_ptr<const PrimaryGraph> primary;
  std::shared_ptr<const ClothMesh> mesh;
  StepFunction step;
  GarmentTerm term;  // over vs behind the shoulder
  // The skeleton and clip pair the primary graph was built from (restoreGarment leaves it
  // unrecorded: the caller has it from the file).
  ClipPairIdentity clips;
};

// The config of `name` with every default; throws Error on an unknown garment.
nlohmann::json defaultGarmentConfig(const std::string& name);
// Fills in defaults and checks names and ranges (Error names the field).
nlohmann::json completeGarmentConfig(const nlohmann::json& config);

// Primary graph, mesh, simulator and garment term from scratch.
Garment buildGarment(const nlohmann::json& config);
// The same from a saved primary graph and mesh (resume, MPI workers): only the simulator and
// the term are rebuilt.
Garment restoreGarment(const nlohmann::json& config, PrimaryGraph primary, ClothMesh mesh);

// The state the exploration starts from at config["initial_node"]: the garment at rest (the
// cape settled along its natural cycle), velocities jittered by ±velocity_jitter m/s from seed.
ClothState initialClothState(const Garment& garment);
uint32_t initialNode(const Garment& garment);

// Garment term: weight × |fraction of vertices in front of the chest plane in a − in b|. The
// plane passes through the mean of `joints` at the node, facing the character's +z.
GarmentTerm shoulderSideTerm(std::shared_ptr<const PrimaryGraph> primary,
                             std::vector<uint32_t> joints, float weight);

}  // namespace throng::secondary
