// Tetrahedral mesh files; see tet_files.hpp.
#include "tet_files.hpp"

#include <cstdio>
#include <memory>

namespace tetmesh {

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File openForWrite(const std::string& path) { return File(std::fopen(path.c_str(), "w"), &std::fclose); }

acd::Status cannotWrite(const std::string& path) {
  return acd::Status::error(acd::StatusCode::FileUnreadable, path + ": cannot write");
}

acd::Status finish(File& f, const std::string& path) {
  const bool bad = std::ferror(f.get()) != 0;
  const int closed = std::fclose(f.release());
  return bad || closed != 0 ? cannotWrite(path) : acd::Status::success();
}

int labelOf(const TetMesh& m, std::size_t t) { return t < m.labels.size() ? m.labels[t] : 0; }

}  // namespace

bool parseTetFormat(const std::string& name, TetFormat& format) {
  if (name == "vtk") return format = TetFormat::Vtk, true;
  if (name == "mesh") return format = TetFormat::Medit, true;
  if (name == "tetgen") return format = TetFormat::TetGen, true;
  return false;
}

std::vector<std::string> tetOutputFiles(const std::string& out, TetFormat format) {
  if (format == TetFormat::TetGen) return {out + ".node", out + ".ele", out + ".face"};
  return {out};
}

acd::Status writeVtk(const std::string& path, const TetMesh& m) {
  File f = openForWrite(path);
  if (!f) return cannotWrite(path);
  std::FILE* o = f.get();
  std::fprintf(o, "# vtk DataFile Version 2.0\ntetmesh: tetrahedra of ACD hulls, labelled by component\nASCII\n");
  std::fprintf(o, "DATASET UNSTRUCTURED_GRID\nPOINTS %zu double\n", m.points.size());
  for (const Vec3& p : m.points) std::fprintf(o, "%.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  std::fprintf(o, "CELLS %zu %zu\n", m.tets.size(), 5 * m.tets.size());
  for (const auto& t : m.tets) std::fprintf(o, "4 %d %d %d %d\n", t[0], t[1], t[2], t[3]);
  std::fprintf(o, "CELL_TYPES %zu\n", m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) std::fprintf(o, "10\n");
  std::fprintf(o, "CELL_DATA %zu\nSCALARS component int 1\nLOOKUP_TABLE default\n", m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) std::fprintf(o, "%d\n", labelOf(m, t));
  return finish(f, path);
}

acd::Status writeMedit(const std::string& path, const TetMesh& m) {
  File f = openForWrite(path);
  if (!f) return cannotWrite(path);
  std::FILE* o = f.get();
  std::fprintf(o, "MeshVersionFormatted 2\nDimension 3\n\nVertices\n%zu\n", m.points.size());
  for (const Vec3& p : m.points) std::fprintf(o, "%.17g %.17g %.17g 0\n", p.x(), p.y(), p.z());
  std::fprintf(o, "\nTriangles\n%zu\n", m.faces.size());
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    std::fprintf(o, "%d %d %d %d\n", m.faces[i][0] + 1, m.faces[i][1] + 1, m.faces[i][2] + 1,
                 i < m.faceMarkers.size() ? m.faceMarkers[i] : 0);
  std::fprintf(o, "\nTetrahedra\n%zu\n", m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const auto& v = m.tets[t];
    std::fprintf(o, "%d %d %d %d %d\n", v[0] + 1, v[1] + 1, v[2] + 1, v[3] + 1, labelOf(m, t));
  }
  std::fprintf(o, "\nEnd\n");
  return finish(f, path);
}

acd::Status writeTetGenFiles(const std::string& base, const TetMesh& m) {
  {
    const std::string path = base + ".node";
    File f = openForWrite(path);
    if (!f) return cannotWrite(path);
    std::fprintf(f.get(), "%zu 3 0 0\n", m.points.size());
    for (std::size_t i = 0; i < m.points.size(); ++i)
      std::fprintf(f.get(), "%zu %.17g %.17g %.17g\n", i + 1, m.points[i].x(), m.points[i].y(), m.points[i].z());
    if (acd::Status s = finish(f, path); !s.ok()) return s;
  }
  {
    const std::string path = base + ".ele";
    File f = openForWrite(path);
    if (!f) return cannotWrite(path);
    std::fprintf(f.get(), "%zu 4 1\n", m.tets.size());
    for (std::size_t t = 0; t < m.tets.size(); ++t) {
      const auto& v = m.tets[t];
      std::fprintf(f.get(), "%zu %d %d %d %d %d\n", t + 1, v[0] + 1, v[1] + 1, v[2] + 1, v[3] + 1, labelOf(m, t));
    }
    if (acd::Status s = finish(f, path); !s.ok()) return s;
  }
  const std::string path = base + ".face";
  File f = openForWrite(path);
  if (!f) return cannotWrite(path);
  std::fprintf(f.get(), "%zu 1\n", m.faces.size());
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    std::fprintf(f.get(), "%zu %d %d %d %d\n", i + 1, m.faces[i][0] + 1, m.faces[i][1] + 1, m.faces[i][2] + 1,
                 i < m.faceMarkers.size() ? m.faceMarkers[i] : 0);
  return finish(f, path);
}

acd::Status writeTetMesh(const std::string& out, TetFormat format, const TetMesh& mesh) {
  switch (format) {
    case TetFormat::Vtk: return writeVtk(out, mesh);
    case TetFormat::Medit: return writeMedit(out, mesh);
    case TetFormat::TetGen: return writeTetGenFiles(out, mesh);
  }
  return acd::Status::error(acd::StatusCode::InvalidParameter, "unknown output format");
}

}  // namespace tetmesh

namespace tetmesh {

acd::Status writePoly(const std::string& path, const Plc& plc) {
  File f = openForWrite(path);
  if (!f) return cannotWrite(path);
  std::FILE* o = f.get();
  std::fprintf(o, "# part 1: nodes\n%zu 3 0 0\n", plc.points.size());
  for (std::size_t i = 0; i < plc.points.size(); ++i)
    std::fprintf(o, "%zu %.17g %.17g %.17g\n", i + 1, plc.points[i].x(), plc.points[i].y(), plc.points[i].z());
  std::fprintf(o, "# part 2: facets\n%zu 1\n", plc.facets.size());
  for (const Plc::Facet& facet : plc.facets) {
    std::fprintf(o, "1 0 %d\n%zu", facet.marker, facet.polygon.size());
    for (int v : facet.polygon) std::fprintf(o, " %d", v + 1);
    std::fprintf(o, "\n");
  }
  std::fprintf(o, "# part 3: holes\n0\n# part 4: regions\n%zu\n", plc.regions.size());
  for (std::size_t r = 0; r < plc.regions.size(); ++r)
    std::fprintf(o, "%zu %.17g %.17g %.17g %d\n", r + 1, plc.regions[r].seed.x(), plc.regions[r].seed.y(),
                 plc.regions[r].seed.z(), plc.regions[r].label);
  return finish(f, path);
}

}  // namespace tetmesh
