// reading a triangle mesh from OFF, OBJ, PLY or STL.
//
// The parsing itself is CGAL's polygon-soup reader (CGAL::IO::read_polygon_soup, CGAL 5.5). What
// this layer adds is what a benchmark needs and CGAL does not give:
//   * an error that names the file and, for the text formats OFF and OBJ, the line;
//   * rejection of NaN / infinite / overflowing coordinates (CGAL's binary PLY and STL readers pass
//     them through; the text readers fail without saying where);
//   * index checks (out of range, fewer than three corners);
//   * a decision about non-triangle faces (fan them, or refuse) and about degenerate faces
//     (repeated corner, or three exactly collinear corners: refuse, drop, or keep).
#pragma once

#include "cases/util/input_error.hpp"

#include <cstddef>
#include <string>
#include <vector>

#include "cases/scenes/mesh.hpp"

namespace tritri::scenes {

// Thrown for every problem with a file. what() reads "FILE:LINE: message" when the line is known,
// "FILE: message" otherwise.
struct MeshError : InputError {
  std::string file;
  std::size_t line;  // 1-based; 0 when unknown (binary formats, or CGAL failed somewhere we could not find)
  MeshError(std::string file_, std::size_t line_, const std::string& msg);
};

enum class Polygons { Fan, Refuse };
enum class Degenerate { Refuse, Drop, Keep };

struct ReadOptions {
  Polygons polygons = Polygons::Fan;
  Degenerate degenerate = Degenerate::Refuse;
};

struct ReadReport {
  std::string format;              // "off", "obj", "ply", "stl"
  std::size_t vertices = 0;
  std::size_t polygons = 0;        // faces in the file
  std::size_t fanned = 0;          // of which had more than three corners
  std::size_t triangles = 0;       // triangles in the result
  std::size_t dropped_degenerate = 0;
  std::size_t unreferenced_vertices = 0;
};

Mesh read_mesh(const std::string& path, const ReadOptions& options = {}, ReadReport* report = nullptr);

}  // namespace tritri::scenes
