// Settings of the dual static/dynamic map and its scan preprocessing (thesis 4.2, 5.3),
// with the YAML parser that checks every key and range.
#pragma once

#include <string>

#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::mapping {

enum class UpdateMode {
  kDynamic,  // Tables 4.1/4.2: people and moved objects go to the dynamic channel.
  kRegular,  // Algorithm 2: standard occupancy update of the static channel only.
};

struct MappingConfig {
  double resolution_m = 0.05;  // m, edge of a leaf voxel.
  // m, the depth (along the Kinect's optical axis, where its noise grows) up to which a
  // return is a hit; farther returns clear free space up to this depth and set no hit. For
  // point clouds without a camera (InsertPointCloud) the distance from the origin.
  double max_range_m = 4.0;
  UpdateMode update = UpdateMode::kDynamic;  // Inverse sensor model (YAML: dynamic|regular).
  double prob_low = 0.4;   // "Low" of Tables 4.1/4.2 (and Algorithm 2's free), in (0, 0.5).
  double prob_high = 0.7;  // "High" of Tables 4.1/4.2 (and Algorithm 2's hit), in (0.5, 1).
  double clamp_min = 0.1192;  // Lower probability clamp of both channels (OctoMap default).
  double clamp_max = 0.971;   // Upper probability clamp of both channels (OctoMap default).
  // A voxel is occupied in a channel when its probability is >= this (OctoMap's rule);
  // it also splits a known static voxel into free / occupied for the tables.
  double occupancy_threshold = 0.5;
  // A known voxel counts as *free* for the tables only once its static probability is
  // below this; between it and occupancy_threshold it still counts as unknown. One grazing
  // ray through a floor or wall voxel is then not enough to bar that voxel from the static
  // map for ever (Free + Occupied gives Low in Table 4.1). 0.5 is the thesis's rule.
  double free_threshold = 0.25;
  // Free space near a measured surface. A voxel the surface only grazes, or that lies on the
  // voxel boundary the surface runs along (the floor at z = 0), is crossed by rays through
  // its empty part; counted as free, such crossings cleared floors and walls from a moving
  // robot's map (and, once free, Table 4.1 keeps them out of the static map for good).
  // A hit ray observes free space only until it comes within this distance, in voxels and
  // measured along the surface normal, of the surface it hit; 0 = up to its end voxel.
  // One voxel is not enough for a surface on a voxel boundary: the free space is traced to
  // the centre of the voxel holding this point, up to half a voxel nearer the surface, and
  // noisy points of the surface fill the voxel layer on either side of the boundary. With
  // one voxel, the floor just in front of the robot, where no nearer hit protects it
  // (surface_band), was cleared and turned dynamic in rings wherever the robot turned.
  double surface_margin_voxels = 2.0;
  // |cos| of the incidence angle below which a hit counts as this grazing (the margin along
  // the ray is at most surface_margin_voxels * resolution_m / min_incidence_cos).
  double min_incidence_cos = 0.1;
  // Voxels next to (26-neighbourhood) a voxel hit in the same scan are not observed free in
  // that scan: the surface may lie in them within one voxel of noise and discretisation.
  bool surface_band = true;
  // The floor is the plane z = 0 of the map frame (the base stands on it), a voxel
  // boundary: floor points fall in the layers just below and just above it. Nothing but
  // feet and chair legs lies in the layer above those, yet the two rules above kept it
  // from being seen free: the margin stopped every floor ray's free space 10 cm up, and
  // the band protected the voxels above every floor hit. A person's feet there stayed in
  // the dynamic map wherever the person had stood; on the thesis scenarios that layer held
  // half of the wrongly kept dynamic points. With floor_plane, a hit in the floor layers
  // (z in [-resolution, resolution)) by a ray from higher up observes free space down to
  // the middle of the layer above them (the trace to that voxel's centre stays above the
  // floor layers), and the band of a hit just above the plane leaves out the voxels above.
  bool floor_plane = true;
  // A ray beside a nearer surface, at a depth edge, observes no free space from where it
  // comes within surface_margin_voxels of that surface's depth: the rays just beside an
  // outline run through the voxels holding its rim. A thin object seen edge-on is all rim:
  // S1's open door leaf (4 cm) in the office, crossed by such rays from the corridor before
  // any ray hit it, went to the dynamic map (Table 4.1) and held most of the static points
  // the missions lost. "Beside" is within this many voxels of the ray, measured across it
  // (robotio::NearestDepthAlongside); 0 = off. Rays ending below the floor layers are
  // exempt: they passed over a hole's edge, and their free space below the floor is what
  // shows the planner the hole. 1.5 rather than 1: office missions kept 0.992-0.994 of
  // their static points against 0.988-0.991, at a cost of at most 0.0004 of the thesis
  // scenarios' DA; 2 cost them up to 0.006 (docs/RESULTS.md). Thin leaves come out a
  // cell thicker, which the planner's squeeze grid allows for.
  double edge_clearance_voxels = 1.5;
  // With edge_clearance_voxels: the Kinect gives no depth where it sees a surface at
  // grazing incidence, so the far part of a wall, a desk top or a shelf side seen along
  // its face is a gap in the image, and the rays beside that part, which run through the
  // air in the voxels holding the face, had no nearer depth beside them and cleared those
  // voxels. Gap pixels within this angle (a square window in the image) of a pixel
  // measured at grazing incidence count, for the depth-edge rule only, as measured at that
  // pixel's depth (robotio::FillGrazingGaps); pixels in the floor layers (floor_plane)
  // seed nothing, since far off the floor is grazing everywhere and filling its gap kept
  // the space around people's feet from being seen free. 0 = off. On a recorded office
  // mission (true poses) 3 deg kept 0.9937 of the static points against 0.9907, at 0.0007
  // of DA; on the door scenario 4 deg cost 0.004 of DA, 3 deg 0.0001 (docs/RESULTS.md).
  double grazing_gap_deg = 3.0;
  // With edge_clearance_voxels: the camera does not see what lies just beside its view, so
  // the rays along the image's left and right edges pass a wall's end just outside it (a
  // jamb seen from the corridor while turning) with nothing beside them, and clear the
  // voxels holding the wall's face there. A surface this near (m) is assumed just outside
  // those edges: rays within edge_clearance * f / this of them stop near this depth, so an
  // unseen surface at least this deep is allowed for. 0 = off, the default: with 1.5 a
  // person walking out at the side of a still robot's view stayed in the dynamic map (DA of
  // the in-view scenario 0.957 -> 0.876, docs/RESULTS.md).
  double unseen_side_depth_m = 0.0;
  // Lasting change (not in the thesis, whose Table 4.1 sends everything that appears in
  // known free space to the dynamic map for good): a voxel of free space that has stayed
  // occupied in the dynamic map is raised towards the static map by a small step per
  // scan that observes it occupied, so that after this many such scans (its static value
  // is at clamp_min by then) it counts as unknown again and the next hits make it static:
  // a door that was closed, a chair put down. Each free observation sets it back by
  // prob_low. A scan is one instant of the rig (both Kinects inserted together), so at
  // 30 Hz the default is 10 s of being seen there: on the thesis scenarios the person who
  // stands 8 and 10 s stays dynamic and the closed door turns static; 200 makes the
  // person static too, 450 leaves the door dynamic (docs/RESULTS.md). 0 = the thesis's
  // rule.
  int persistence_observations = 300;
  double voxel_filter_m = 0.05;  // m, leaf of the preprocessing voxel grid (base frame).
  // Threads that share a scan's per-ray work (ScanIntegrator); the map is the same for any
  // number. Two: the machine the thesis's rate is asked of has two cores.
  int insert_threads = 2;
};

[[nodiscard]] const char* UpdateModeName(UpdateMode mode);

// Parses a `mapping:` mapping (all keys optional; defaults as above). Throws
// robotio::ConfigError naming the file, key and allowed range.
[[nodiscard]] MappingConfig ParseMappingConfig(robotio::ConfigNode& node);

// Checks the relations between fields that single-key ranges cannot express
// (low < 0.5 < high, clamp_min < clamp_max, ...); the message names `source`.
[[nodiscard]] robotio::Status ValidateMappingConfig(const MappingConfig& config,
                                                    const std::string& source);

[[nodiscard]] robotio::Expected<MappingConfig> LoadMappingConfig(const std::string& file);

}  // namespace dynamap::mapping
