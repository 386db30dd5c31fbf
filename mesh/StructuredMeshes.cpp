#include "StructuredMeshes.hpp"

#include <cmath>

namespace chute::mesh {

namespace {
int addNamed(Model& m, const std::string& base, const Vec3& x) {
  return m.addNode(x, base + "." + std::to_string(m.numNodes()));
}
void addElement(Model& m, std::initializer_list<int> nodes, int set, int material) {
  MembraneElement e;
  int k = 0;
  for (int n : nodes) e.nodes[k++] = n;
  e.numNodes = k;
  e.set = set;
  e.material = material;
  m.membranes.push_back(e);
}
void rename(Model& m, int node, const std::string& name) {
  m.nodeByName.erase(m.nodeName[node]);
  m.nodeName[node] = name;
  m.nodeByName[name] = node;
}
}  // namespace

void addDisk(Model& m, const std::string& name, int set, int material, const Vec3& centre,
             double radius, int rings) {
  auto& all = m.nodeSets[name];
  const int c = addNamed(m, name, centre);
  rename(m, c, name + ".center");
  all.push_back(c);
  std::vector<int> inner{c}, outer;
  for (int k = 1; k <= rings; ++k) {
    outer.clear();
    for (int j = 0; j < 6 * k; ++j) {
      const double th = 2.0 * M_PI * j / (6.0 * k), r = radius * k / rings;
      outer.push_back(addNamed(m, name, centre + Vec3(r * std::cos(th), r * std::sin(th), 0.0)));
    }
    all.insert(all.end(), outer.begin(), outer.end());
    auto O = [&](int i) { return outer[i % (6 * k)]; };
    auto I = [&](int i) { return k == 1 ? c : inner[i % (6 * (k - 1))]; };
    for (int s = 0; s < 6; ++s) {
      for (int j = 0; j < k; ++j)
        addElement(m, {O(s * k + j), O(s * k + j + 1), I(s * (k - 1) + j)}, set, material);
      for (int j = 0; j + 1 < k; ++j)
        addElement(m, {I(s * (k - 1) + j), O(s * k + j + 1), I(s * (k - 1) + j + 1)}, set,
                   material);
    }
    inner = outer;
  }
  m.nodeSets[name + ".rim"] = outer;
}

void addRectangle(Model& m, const std::string& name, int set, int material, const Vec3& corner,
                  double lx, double ly, int nx, int ny, bool quads) {
  std::vector<int> id((nx + 1) * (ny + 1));
  auto at = [&](int i, int j) -> int& { return id[j * (nx + 1) + i]; };
  auto& all = m.nodeSets[name];
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      at(i, j) = addNamed(m, name, corner + Vec3(lx * i / nx, ly * j / ny, 0.0));
      all.push_back(at(i, j));
      if (i == 0) m.nodeSets[name + ".xmin"].push_back(at(i, j));
      if (i == nx) m.nodeSets[name + ".xmax"].push_back(at(i, j));
      if (j == 0) m.nodeSets[name + ".ymin"].push_back(at(i, j));
      if (j == ny) m.nodeSets[name + ".ymax"].push_back(at(i, j));
      if (i == 0 || i == nx || j == 0 || j == ny) m.nodeSets[name + ".edge"].push_back(at(i, j));
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (quads) {
        addElement(m, {a, b, c, d}, set, material);
      } else if ((i + j) % 2 == 0) {
        addElement(m, {a, b, c}, set, material);
        addElement(m, {a, c, d}, set, material);
      } else {
        addElement(m, {a, b, d}, set, material);
        addElement(m, {b, c, d}, set, material);
      }
    }
  rename(m, at(0, 0), name + ".c00");
  rename(m, at(nx, 0), name + ".c10");
  rename(m, at(nx, ny), name + ".c11");
  rename(m, at(0, ny), name + ".c01");
  if (nx % 2 == 0 && ny % 2 == 0) rename(m, at(nx / 2, ny / 2), name + ".center");
}

}  // namespace chute::mesh
