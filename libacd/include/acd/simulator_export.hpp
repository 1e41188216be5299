// Files a physics engine or robot simulator loads directly: one mesh file per hull (OBJ, STL),
// glTF/GLB with one mesh node per hull (acd/algo/gltf_export.hpp), and rigid-body descriptions that
// use the hulls as collision shapes and the model as the visual: URDF (ROS, PyBullet, Isaac,
// Drake), MJCF (MuJoCo) and SDF (Gazebo). The XML is written with tinyxml2.
//
// Layout inside the output folder (names fixed, so the descriptions can refer to them):
//   hulls/hull_NNN.obj, hulls/hull_NNN.stl   one file per hull (STL also for URDF/MJCF/SDF)
//   model.stl                                the model, the visual of URDF/MJCF/SDF
//   model.urdf, model.xml (MJCF), model.sdf  one rigid body: the hulls as its collision shapes
//   hulls.glb, or hulls.gltf + hulls.bin     one mesh node per hull
// Lengths are the input's, unscaled (simulators read metres); mass and inertia follow from the
// density in mass per unit length cubed.
#pragma once

#include <acd/algo/mass_properties.hpp>
#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <vector>

namespace acd {

enum class SimFormat { Obj, Stl, Glb, Gltf, Urdf, Mjcf, Sdf };

/// "obj", "stl", "glb", "gltf", "urdf", "mjcf", "sdf" (case-insensitive); false otherwise.
bool parseSimFormat(const std::string& name, SimFormat& format);
const char* toString(SimFormat format);

struct SimulatorModel {
  std::string name = "model";   // robot / model / body name (XML names: letters, digits, _ - .)
  TriMesh visual;               // the model, closed, outward
  std::vector<TriMesh> hulls;   // collision shapes, convex, closed, outward
  MassProperties mass;          // of the model at the chosen density
};

/// Writes the files of every requested format into `dir` (which must exist); `written` gets
/// their paths relative to `dir`, in a fixed order. A file that cannot be written comes back
/// as a Status naming it.
Status writeSimulatorFiles(const std::string& dir, const SimulatorModel& model, const std::vector<SimFormat>& formats,
                           std::vector<std::string>* written = nullptr);

/// A name usable in URDF/SDF/MJCF: characters other than letters, digits, '_', '-', '.' become
/// '_', and it never starts with a digit or is empty.
std::string simulatorName(const std::string& raw);

}  // namespace acd
