#include "anvil/mesh/mesh_io.h"

#include "anvil/core/error.h"
#include "anvil/core/input_file.h"
#include "anvil/mesh/node_budget.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <unordered_map>

namespace anvil::mesh {
namespace {

/// `path` when it is a mesh file that may be opened (a regular file of at
/// most kMaxMeshBytes); throws InputError otherwise.
const std::string& readable(const std::string& path) {
  if (const std::string problem = input_file_problem(path, kMaxMeshBytes); !problem.empty())
    throw InputError(path + ": cannot open the mesh file: " + problem);
  return path;
}

/// Whitespace-separated tokens of a text file with the line each came from,
/// so that every error names file and line.
class Tokens {
public:
  explicit Tokens(const std::string& path) : path_(path), in_(readable(path)) {
    if (!in_) throw InputError(path + ": cannot open the mesh file");
    std::error_code error;
    bytes_ = static_cast<long>(std::filesystem::file_size(path, error));
    if (error) bytes_ = 0;
  }

  bool at_end() { return !fill(); }

  std::string word() {
    if (!fill()) fail("unexpected end of file");
    std::string w;
    line_stream_ >> w;
    return w;
  }

  template <class T> T number(const char* what) {
    const std::string w = word();
    std::istringstream s(w);
    T value{};
    if (!(s >> value) || !s.eof()) fail(std::string("expected ") + what + ", found '" + w + "'");
    if constexpr (std::is_floating_point_v<T>)
      if (!std::isfinite(value)) fail(std::string("expected ") + what + ", found '" + w + "' (not finite)");
    return value;
  }

  /// A count of entries that follow: at least 0, and no more than the file's
  /// bytes could hold (a damaged count must not allocate the machine away).
  long count(const char* what) {
    const long n = number<long>(what);
    if (n < 0 || n > bytes_)
      fail(std::string("expected ") + what + " between 0 and the file's size, found " + std::to_string(n));
    return n;
  }

  /// A count of nodes that follow: as count(), and within the nodes this
  /// machine can solve (mesh/node_budget), before any is read.
  long node_count(const char* what) {
    const long n = count(what);
    check_node_budget(static_cast<double>(n), where(path_, line_) + ": " + std::to_string(n) + " nodes");
    return n;
  }

  /// Skips tokens up to and including `keyword`.
  void skip_to(const std::string& keyword) {
    while (word() != keyword) {
    }
  }

  [[noreturn]] void fail(const std::string& message) const { throw InputError(where(path_, line_) + ": " + message); }

private:
  bool fill() {
    for (;;) {
      line_stream_ >> std::ws;
      if (!line_stream_.eof() && line_stream_.peek() != '#') return true;
      std::string line;
      if (!std::getline(in_, line)) return false;
      ++line_;
      line_stream_.clear();
      line_stream_.str(line);
    }
  }

  std::string path_;
  std::ifstream in_;
  long bytes_ = 0;
  std::istringstream line_stream_;
  int line_ = 0;
};

/// Collects nodes by file id, then renumbers densely.
struct RawMesh {
  std::vector<Point> nodes;
  std::unordered_map<long, int> index_of_id;
  std::vector<std::array<long, 4>> tets; // file ids
  std::vector<std::array<long, 3>> triangles;
  std::vector<int> triangle_tags;

  void add_node(long id, const Point& x, Tokens& tokens) {
    if (!index_of_id.emplace(id, static_cast<int>(nodes.size())).second)
      tokens.fail("node " + std::to_string(id) + " is defined twice");
    nodes.push_back(x);
  }

  TetMesh finish(const std::string& path) const {
    TetMesh mesh;
    mesh.nodes = nodes;
    auto index = [&](long id, const char* kind, std::size_t element) {
      auto it = index_of_id.find(id);
      if (it == index_of_id.end())
        throw InputError(path + ": " + kind + " " + std::to_string(element + 1) + " refers to node " +
                         std::to_string(id) + ", which is not defined");
      return it->second;
    };
    for (std::size_t e = 0; e < tets.size(); ++e) {
      Tet t;
      for (int a = 0; a < 4; ++a)
        t[a] = index(tets[e][a], "tetrahedron", e);
      mesh.tets.push_back(t);
    }
    std::vector<Triangle> tagged;
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      Triangle t;
      for (int a = 0; a < 3; ++a)
        t[a] = index(triangles[f][a], "triangle", f);
      tagged.push_back(t);
    }
    validate(mesh, path);
    build_boundary(mesh, tagged, triangle_tags);
    return mesh;
  }
};

void read_gmsh2(Tokens& tokens, RawMesh& raw) {
  for (;;) {
    if (tokens.at_end()) return;
    const std::string section = tokens.word();
    if (section == "$Nodes") {
      const long n = tokens.node_count("a node count");
      for (long i = 0; i < n; ++i) {
        const long id = tokens.number<long>("a node id");
        const double x = tokens.number<double>("x"), y = tokens.number<double>("y"), z = tokens.number<double>("z");
        raw.add_node(id, Point(x, y, z), tokens);
      }
      tokens.skip_to("$EndNodes");
    } else if (section == "$Elements") {
      const long n = tokens.count("an element count");
      for (long i = 0; i < n; ++i) {
        tokens.number<long>("an element id");
        const int type = tokens.number<int>("an element type");
        const long tag_count = tokens.count("a tag count");
        int physical = 0;
        for (int t = 0; t < tag_count; ++t) {
          const int tag = tokens.number<int>("a tag");
          if (t == 0) physical = tag;
        }
        const int node_count = type == 4 ? 4 : type == 2 ? 3 : type == 15 ? 1 : type == 1 ? 2 : -1;
        if (node_count < 0)
          tokens.fail("element type " + std::to_string(type) +
                      " is not supported (linear tets, triangles, lines, points)");
        std::array<long, 4> v{};
        for (int a = 0; a < node_count; ++a)
          v[a] = tokens.number<long>("a node id");
        if (type == 4) raw.tets.push_back(v);
        if (type == 2) {
          raw.triangles.push_back({v[0], v[1], v[2]});
          raw.triangle_tags.push_back(physical);
        }
      }
      tokens.skip_to("$EndElements");
    } else if (section.rfind("$End", 0) != 0 && section[0] == '$') {
      tokens.skip_to("$End" + section.substr(1));
    }
  }
}

void read_gmsh4(Tokens& tokens, RawMesh& raw) {
  std::unordered_map<int, int> surface_physical; // surface entity tag -> first physical tag
  for (;;) {
    if (tokens.at_end()) return;
    const std::string section = tokens.word();
    if (section == "$Entities") {
      long counts[4];
      for (auto& c : counts)
        c = tokens.count("an entity count");
      for (int dim = 0; dim < 4; ++dim)
        for (long i = 0; i < counts[dim]; ++i) {
          const int tag = tokens.number<int>("an entity tag");
          for (int c = 0; c < (dim == 0 ? 3 : 6); ++c)
            tokens.number<double>("a bounding coordinate");
          const long physical_count = tokens.count("a physical tag count");
          for (long p = 0; p < physical_count; ++p) {
            const int physical = tokens.number<int>("a physical tag");
            if (dim == 2 && p == 0) surface_physical[tag] = physical;
          }
          if (dim > 0) {
            const long bounding = tokens.count("a bounding entity count");
            for (long b = 0; b < bounding; ++b)
              tokens.number<long>("a bounding entity tag");
          }
        }
      tokens.skip_to("$EndEntities");
    } else if (section == "$Nodes") {
      const long blocks = tokens.count("a block count");
      tokens.node_count("a node count");
      tokens.number<long>("a min node tag");
      tokens.number<long>("a max node tag");
      for (long b = 0; b < blocks; ++b) {
        tokens.number<int>("an entity dimension");
        tokens.number<int>("an entity tag");
        if (tokens.number<int>("the parametric flag") != 0) tokens.fail("parametric nodes are not supported");
        const long n = tokens.count("a node count");
        std::vector<long> ids(static_cast<std::size_t>(n));
        for (auto& id : ids)
          id = tokens.number<long>("a node tag");
        for (long id : ids) {
          const double x = tokens.number<double>("x"), y = tokens.number<double>("y"), z = tokens.number<double>("z");
          raw.add_node(id, Point(x, y, z), tokens);
        }
      }
      tokens.skip_to("$EndNodes");
    } else if (section == "$Elements") {
      const long blocks = tokens.count("a block count");
      for (int c = 0; c < 3; ++c)
        tokens.number<long>("an element count or tag");
      for (long b = 0; b < blocks; ++b) {
        tokens.number<int>("an entity dimension");
        const int entity = tokens.number<int>("an entity tag");
        const int type = tokens.number<int>("an element type");
        const long n = tokens.count("an element count");
        const int node_count = type == 4 ? 4 : type == 2 ? 3 : type == 15 ? 1 : type == 1 ? 2 : -1;
        if (node_count < 0)
          tokens.fail("element type " + std::to_string(type) +
                      " is not supported (linear tets, triangles, lines, points)");
        for (long i = 0; i < n; ++i) {
          tokens.number<long>("an element tag");
          std::array<long, 4> v{};
          for (int a = 0; a < node_count; ++a)
            v[a] = tokens.number<long>("a node tag");
          if (type == 4) raw.tets.push_back(v);
          if (type == 2) {
            raw.triangles.push_back({v[0], v[1], v[2]});
            auto it = surface_physical.find(entity);
            raw.triangle_tags.push_back(it == surface_physical.end() ? entity : it->second);
          }
        }
      }
      tokens.skip_to("$EndElements");
    } else if (section[0] == '$' && section.rfind("$End", 0) != 0) {
      tokens.skip_to("$End" + section.substr(1));
    }
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

} // namespace

TetMesh read_gmsh(const std::string& path) {
  Tokens tokens(path);
  if (tokens.word() != "$MeshFormat") tokens.fail("expected $MeshFormat: not a Gmsh ASCII file");
  const std::string version = tokens.word();
  const bool version_2 = version.rfind("2.2", 0) == 0, version_4 = version.rfind("4.1", 0) == 0;
  if (!version_2 && !version_4) tokens.fail("Gmsh format " + version + " is not supported (2.2 or 4.1)");
  if (tokens.number<int>("the file type (0 = ASCII)") != 0)
    tokens.fail("binary Gmsh files are not supported; save as ASCII");
  tokens.number<int>("the data size");
  tokens.skip_to("$EndMeshFormat");
  RawMesh raw;
  if (version_2)
    read_gmsh2(tokens, raw);
  else
    read_gmsh4(tokens, raw);
  return raw.finish(path);
}

TetMesh read_medit(const std::string& path) {
  Tokens tokens(path);
  RawMesh raw;
  for (;;) {
    if (tokens.at_end()) break;
    const std::string keyword = lower(tokens.word());
    if (keyword == "end") break;
    if (keyword == "meshversionformatted") {
      tokens.number<int>("a version");
    } else if (keyword == "dimension") {
      if (tokens.number<int>("the dimension") != 3) tokens.fail("only 3D meshes are supported (Dimension 3)");
    } else if (keyword == "vertices") {
      const long n = tokens.node_count("a vertex count");
      for (long i = 0; i < n; ++i) {
        const double x = tokens.number<double>("x"), y = tokens.number<double>("y"), z = tokens.number<double>("z");
        tokens.number<int>("a vertex reference");
        raw.add_node(i + 1, Point(x, y, z), tokens);
      }
    } else if (keyword == "triangles") {
      const long n = tokens.count("a triangle count");
      for (long i = 0; i < n; ++i) {
        std::array<long, 3> v{};
        for (auto& x : v)
          x = tokens.number<long>("a vertex number");
        raw.triangles.push_back(v);
        raw.triangle_tags.push_back(tokens.number<int>("a triangle reference"));
      }
    } else if (keyword == "tetrahedra") {
      const long n = tokens.count("a tetrahedron count");
      for (long i = 0; i < n; ++i) {
        std::array<long, 4> v{};
        for (auto& x : v)
          x = tokens.number<long>("a vertex number");
        tokens.number<int>("a tetrahedron reference");
        raw.tets.push_back(v);
      }
    } else if (keyword == "edges" || keyword == "corners" || keyword == "ridges" || keyword == "requiredvertices") {
      const long n = tokens.count("a count");
      const int per = keyword == "edges" ? 3 : 1;
      for (long i = 0; i < n * per; ++i)
        tokens.number<long>("an entry");
    } else {
      tokens.fail("unknown Medit keyword '" + keyword + "'");
    }
  }
  return raw.finish(path);
}

TetMesh read_mesh(const std::string& path) {
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : lower(path.substr(dot));
  if (ext == ".msh") return read_gmsh(path);
  if (ext == ".mesh") return read_medit(path);
  throw InputError(path + ": unknown mesh format '" + ext + "' (expected .msh or .mesh)");
}

} // namespace anvil::mesh
