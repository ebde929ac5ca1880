// mesh reader on top of CGAL's polygon-soup IO. See mesh_io.hpp.
#include "cases/scenes/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

namespace tritri::scenes {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

std::string format_message(const std::string& file, std::size_t line, const std::string& msg) {
  std::ostringstream s;
  s << file;
  if (line) s << ':' << line;
  s << ": " << msg;
  return s.str();
}

std::string lower_extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// ---------------------------------------------------------------------------------------------
// Line locator for the text formats. CGAL's readers report failure as a bare `false`; this scan
// re-reads OFF or OBJ line by line, only to say where a problem is and what it is. It assumes the
// usual layout (one vertex or face per line); if a file does not follow it, the messages lose the
// line but the reading itself (CGAL's) is unaffected.
struct TextScan {
  bool usable = false;                       // false: binary or a layout we do not follow
  std::vector<std::size_t> vertex_line;      // line of vertex i
  std::vector<std::size_t> face_line;        // line of face j
  std::optional<std::pair<std::size_t, std::string>> first_error;
};

std::vector<std::string> tokens_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  std::string t;
  while (s >> t) out.push_back(t);
  return out;
}

// Parses a whole token as a double. Returns an error text, or empty on success.
std::string parse_coordinate(const std::string& tok, double& out) {
  errno = 0;
  char* end = nullptr;
  out = std::strtod(tok.c_str(), &end);
  if (end == tok.c_str() || *end != '\0') return "'" + tok + "' is not a number";
  if (std::isnan(out)) return "coordinate '" + tok + "' is NaN";
  if (std::isinf(out)) {
    return errno == ERANGE ? "coordinate '" + tok + "' overflows a double"
                           : "coordinate '" + tok + "' is infinite";
  }
  return {};
}

bool parse_integer(const std::string& tok, long long& out) {
  errno = 0;
  char* end = nullptr;
  out = std::strtoll(tok.c_str(), &end, 10);
  return end != tok.c_str() && *end == '\0' && errno == 0;
}

TextScan scan_off(const std::string& path) {
  TextScan r;
  std::ifstream in(path);
  std::string line;
  std::size_t lineno = 0;
  enum { Header, Counts, Vertices, Faces, Done } state = Header;
  long long nv = 0, nf = 0;
  int dim = 3;
  auto fail = [&](const std::string& msg) {
    if (!r.first_error) r.first_error = std::make_pair(lineno, msg);
  };
  while (state != Done && std::getline(in, line)) {
    ++lineno;
    if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
    auto toks = tokens_of(line);
    if (toks.empty()) continue;
    std::size_t k = 0;
    if (state == Header) {
      const std::string& kw = toks[0];
      if (kw.size() < 3 || kw.compare(kw.size() - 3, 3, "OFF") != 0) {
        // CGAL also accepts a header-less OFF (counts first); follow it.
        state = Counts;
      } else {
        if (kw.find('n') != std::string::npos) return r;        // nOFF: dimension in file
        if (kw.find('4') != std::string::npos) dim = 4;
        if (toks.size() > 1 && toks[1] == "BINARY") return r;   // binary OFF: no lines
        k = 1;
        state = Counts;
        if (k == toks.size()) continue;
      }
    }
    if (state == Counts) {
      if (toks.size() - k < 2 || !parse_integer(toks[k], nv) || !parse_integer(toks[k + 1], nf) ||
          nv < 0 || nf < 0) {
        fail("expected the counts 'vertices faces [edges]'");
        return r.usable = true, r;
      }
      state = nv > 0 ? Vertices : (nf > 0 ? Faces : Done);
      continue;
    }
    if (state == Vertices) {
      r.vertex_line.push_back(lineno);
      if (toks.size() < std::size_t(dim)) fail("vertex " + std::to_string(r.vertex_line.size() - 1) +
                                               ": fewer than " + std::to_string(dim) + " coordinates");
      for (int i = 0; i < dim && i < int(toks.size()); ++i) {
        double x;
        if (auto e = parse_coordinate(toks[i], x); !e.empty())
          fail("vertex " + std::to_string(r.vertex_line.size() - 1) + ": " + e);
      }
      if (static_cast<long long>(r.vertex_line.size()) == nv) state = nf > 0 ? Faces : Done;
      continue;
    }
    if (state == Faces) {
      const std::size_t j = r.face_line.size();
      r.face_line.push_back(lineno);
      long long n = 0;
      if (!parse_integer(toks[0], n) || n < 0) {
        fail("face " + std::to_string(j) + ": '" + toks[0] + "' is not a corner count");
      } else if (toks.size() < std::size_t(n) + 1) {
        fail("face " + std::to_string(j) + ": " + std::to_string(n) + " corners announced, " +
             std::to_string(toks.size() - 1) + " given");
      } else {
        for (long long i = 1; i <= n; ++i) {
          long long v;
          if (!parse_integer(toks[i], v)) fail("face " + std::to_string(j) + ": '" + toks[i] + "' is not an index");
          else if (v < 0 || v >= nv)
            fail("face " + std::to_string(j) + ": index " + toks[i] + " outside [0, " + std::to_string(nv) + ")");
        }
      }
      if (static_cast<long long>(r.face_line.size()) == nf) state = Done;
    }
  }
  r.usable = true;
  if (state == Vertices) fail("file ends after " + std::to_string(r.vertex_line.size()) + " of " +
                              std::to_string(nv) + " vertices");
  else if (state == Faces) fail("file ends after " + std::to_string(r.face_line.size()) + " of " +
                                std::to_string(nf) + " faces");
  return r;
}

TextScan scan_obj(const std::string& path) {
  TextScan r;
  r.usable = true;
  std::ifstream in(path);
  std::string line;
  std::size_t lineno = 0;
  auto fail = [&](const std::string& msg) {
    if (!r.first_error) r.first_error = std::make_pair(lineno, msg);
  };
  std::vector<std::size_t> face_pending;
  while (std::getline(in, line)) {
    ++lineno;
    if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
    auto toks = tokens_of(line);
    if (toks.empty()) continue;
    if (toks[0] == "v") {
      r.vertex_line.push_back(lineno);
      if (toks.size() < 4) fail("vertex " + std::to_string(r.vertex_line.size() - 1) + ": fewer than 3 coordinates");
      for (int i = 1; i <= 3 && i < int(toks.size()); ++i) {
        double x;
        if (auto e = parse_coordinate(toks[i], x); !e.empty())
          fail("vertex " + std::to_string(r.vertex_line.size() - 1) + ": " + e);
      }
    } else if (toks[0] == "f") {
      const std::size_t j = r.face_line.size();
      r.face_line.push_back(lineno);
      if (toks.size() < 4) fail("face " + std::to_string(j) + ": fewer than 3 corners");
      for (std::size_t i = 1; i < toks.size(); ++i) {
        long long v;
        const std::string head = toks[i].substr(0, toks[i].find('/'));
        if (!parse_integer(head, v) || v == 0) { fail("face " + std::to_string(j) + ": '" + toks[i] + "' is not an index"); continue; }
        // OBJ is 1-based; negative indices count back from the last vertex read so far.
        const long long nv = static_cast<long long>(r.vertex_line.size());
        const long long z = v > 0 ? v - 1 : nv + v;
        if (z < 0 || (v > 0 && z >= nv)) face_pending.push_back(lineno);  // may be a forward reference
      }
    }
  }
  (void)face_pending;  // forward references are legal in OBJ; range is checked after reading
  return r;
}

// STL: CGAL's reader welds equal points through a std::map<Point, int>; a NaN coordinate compares
// "equivalent" to anything there, so a NaN corner silently becomes some other vertex. The raw
// coordinates are therefore checked before CGAL sees them (binary: by facet and corner; ASCII:
// by line).
TextScan scan_stl(const std::string& path) {
  TextScan r;
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50ull * n) {  // binary
      for (std::uint32_t k = 0; k < n && !r.first_error; ++k)
        for (int c = 0; c < 3; ++c) {
          float xyz[3];
          std::memcpy(xyz, bytes.data() + 84 + 50ull * k + 12 + 12 * c, 12);
          for (float x : xyz)
            if (!std::isfinite(x) && !r.first_error)
              r.first_error = std::make_pair(std::size_t(0), "facet " + std::to_string(k) + " corner " +
                                                                 std::to_string(c) + ": coordinate is " +
                                                                 (std::isnan(x) ? "NaN" : "infinite"));
        }
      return r;
    }
  }
  r.usable = true;  // ASCII
  std::istringstream text(bytes);
  std::string line;
  std::size_t lineno = 0;
  while (std::getline(text, line) && !r.first_error) {
    ++lineno;
    auto toks = tokens_of(line);
    if (toks.size() >= 1 && toks[0] == "vertex") {
      if (toks.size() < 4) { r.first_error = std::make_pair(lineno, std::string("vertex with fewer than 3 coordinates")); break; }
      for (int i = 1; i <= 3; ++i) {
        double x;
        if (auto e = parse_coordinate(toks[i], x); !e.empty()) { r.first_error = std::make_pair(lineno, e); break; }
      }
    }
  }
  return r;
}

// Runs CGAL's reader with its messages captured, so that they can go into our error.
template <class Points, class Polys>
bool cgal_read(const std::string& path, Points& points, Polys& polys, std::string& messages) {
  std::ostringstream captured;
  std::ostringstream chatter;  // the STL reader talks on std::cout when verbose
  std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
  std::streambuf* old_out = std::cout.rdbuf(chatter.rdbuf());
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polys, CGAL::parameters::verbose(true));
  } catch (const std::exception& e) {
    captured << "exception: " << e.what();
    ok = false;
  }
  std::cerr.rdbuf(old);
  std::cout.rdbuf(old_out);
  messages = captured.str();
  while (!messages.empty() && std::isspace(static_cast<unsigned char>(messages.back()))) messages.pop_back();
  for (char& c : messages) if (c == '\n') c = ' ';
  return ok;
}

// Refuses a file that cannot be opened or is empty, before any reader sees it.
void check_readable(const std::string& path) {
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw MeshError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  if (probe.peek() == std::char_traits<char>::eof()) throw MeshError(path, 0, "file is empty");
}

// Our own scan of a text format, for line numbers and the errors CGAL lets through (PLY: none).
TextScan scan_text(const std::string& path, const std::string& format) {
  if (format == "off") return scan_off(path);
  if (format == "obj") return scan_obj(path);
  if (format != "stl") return {};
  TextScan scan = scan_stl(path);
  if (scan.first_error) throw MeshError(path, scan.first_error->first, scan.first_error->second);
  return scan;
}

// Polygon j (read at `line`) of a mesh whose vertices are `points`, as triangles added to `mesh`
// (a fan from its first corner), as the options say for polygons and degenerate triangles.
void add_polygon(const std::vector<std::size_t>& f, std::size_t j, std::size_t line,
                 const std::vector<K::Point_3>& points, const ReadOptions& options, const std::string& path,
                 Mesh& mesh, std::vector<char>& used, ReadReport& rep) {
  if (f.size() < 3)
    throw MeshError(path, line, "face " + std::to_string(j) + " has " + std::to_string(f.size()) + " corners");
  for (std::size_t v : f)
    if (v >= points.size())
      throw MeshError(path, line, "face " + std::to_string(j) + ": vertex index " + std::to_string(v) +
                                      " outside [0, " + std::to_string(points.size()) + ")");
  if (f.size() > 3) {
    if (options.polygons == Polygons::Refuse)
      throw MeshError(path, line, "face " + std::to_string(j) + " has " + std::to_string(f.size()) +
                                      " corners and polygons are refused");
    ++rep.fanned;
  }
  // A fan from the first corner: right for convex polygons, which is what mesh files carry in
  // practice; a non-convex polygon can give overlapping triangles (not checked).
  for (std::size_t k = 1; k + 1 < f.size(); ++k) {
    const std::size_t a = f[0], b = f[k], c = f[k + 1];
    std::string why;
    if (a == b || b == c || a == c) why = "repeats a vertex";
    else if (CGAL::collinear(points[a], points[b], points[c])) why = "has collinear corners (zero area)";
    if (!why.empty()) {
      if (options.degenerate == Degenerate::Refuse) {
        std::string which = "face " + std::to_string(j);
        if (f.size() > 3) which += " (fan triangle " + std::to_string(k - 1) + ")";
        throw MeshError(path, line, which + " is degenerate: it " + why);
      }
      if (options.degenerate == Degenerate::Drop) { ++rep.dropped_degenerate; continue; }
    }
    mesh.faces.push_back({std::uint32_t(a), std::uint32_t(b), std::uint32_t(c)});
    used[a] = used[b] = used[c] = 1;
  }
}

}  // namespace

MeshError::MeshError(std::string file_, std::size_t line_, const std::string& msg)
    : InputError(format_message(file_, line_, msg)), file(std::move(file_)), line(line_) {}

Mesh read_mesh(const std::string& path, const ReadOptions& options, ReadReport* report) {
  ReadReport rep;
  rep.format = lower_extension(path);
  if (rep.format != "off" && rep.format != "obj" && rep.format != "ply" && rep.format != "stl")
    throw MeshError(path, 0, "unknown extension '" + rep.format + "' (OFF, OBJ, PLY or STL)");
  check_readable(path);
  const TextScan scan = scan_text(path, rep.format);
  auto vline = [&](std::size_t i) { return i < scan.vertex_line.size() ? scan.vertex_line[i] : 0; };
  auto fline = [&](std::size_t j) { return j < scan.face_line.size() ? scan.face_line[j] : 0; };

  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polys;
  std::string cgal_messages;
  const bool ok = cgal_read(path, points, polys, cgal_messages);
  if (!ok) {
    if (scan.first_error) throw MeshError(path, scan.first_error->first, scan.first_error->second);
    throw MeshError(path, 0, "CGAL could not read it as " + rep.format +
                                 (cgal_messages.empty() ? std::string() : " (CGAL: " + cgal_messages + ")"));
  }
  // CGAL read it. The text scan may still have found something CGAL let through.
  if (scan.first_error) throw MeshError(path, scan.first_error->first, scan.first_error->second);
  if (polys.empty()) throw MeshError(path, 0, "no faces");

  Mesh mesh;
  mesh.name = path;
  rep.vertices = points.size();
  rep.polygons = polys.size();
  mesh.vertices.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const K::Point_3& p = points[i];
    const Vec3 v{p.x(), p.y(), p.z()};
    if (!v.allFinite())
      throw MeshError(path, vline(i), "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
    mesh.vertices.push_back(v);
  }
  if (points.size() > 0xFFFFFFFFull) throw MeshError(path, 0, "more than 2^32 vertices");

  std::vector<char> used(points.size(), 0);
  for (std::size_t j = 0; j < polys.size(); ++j) add_polygon(polys[j], j, fline(j), points, options, path, mesh, used, rep);
  if (mesh.faces.empty()) throw MeshError(path, 0, "no non-degenerate triangle");
  rep.triangles = mesh.faces.size();
  rep.unreferenced_vertices = std::size_t(std::count(used.begin(), used.end(), 0));
  if (report) *report = rep;
  return mesh;
}

}  // namespace tritri::scenes
