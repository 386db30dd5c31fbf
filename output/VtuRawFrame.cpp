#include "VtuRawFrame.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace chute {

namespace {
static_assert(std::endian::native == std::endian::little, "the files say LittleEndian");

// The appended block: each array is a UInt32 byte count followed by its bytes; the XML names
// each array's offset into this block.
class AppendedBlock {
 public:
  size_t offset() const { return bytes_.size(); }
  template <class T>
  void add(const T* data, size_t count) {
    const size_t n = count * sizeof(T);
    if (n > std::numeric_limits<uint32_t>::max())
      throw std::length_error("a VTU array above 4 GiB cannot be written raw");
    const auto header = static_cast<uint32_t>(n);
    append(&header, sizeof header);
    append(data, n);
  }
  void addStrings(const std::vector<std::string>& strings) {
    std::string joined;  // each string followed by a NUL, as VTK writes string arrays
    for (const auto& s : strings) joined.append(s).push_back('\0');
    add(joined.data(), joined.size());
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void append(const void* p, size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

void append(fmt::memory_buffer& b, std::string_view s) {
  b.append(s.data(), s.data() + s.size());
}

// One <DataArray> of the piece: its line in the XML, its bytes in the appended block. Component
// names as VTK's own writer spells them (ComponentName0="...", ...), which its reader and
// ParaView read back.
template <class T>
void appendedArray(fmt::memory_buffer& xml, AppendedBlock& block, const char* type,
                   std::string_view name, int components, const T* data, size_t count,
                   const std::vector<std::string>& componentNames = {}) {
  fmt::format_to(std::back_inserter(xml), FMT_COMPILE("        <DataArray type=\"{}\" Name=\"{}\""),
                 type, name);
  if (components != 1)
    fmt::format_to(std::back_inserter(xml), FMT_COMPILE(" NumberOfComponents=\"{}\""), components);
  for (size_t c = 0; c < componentNames.size(); ++c)
    fmt::format_to(std::back_inserter(xml), FMT_COMPILE(" ComponentName{}=\"{}\""), c,
                   componentNames[c]);
  fmt::format_to(std::back_inserter(xml), FMT_COMPILE(" format=\"appended\" offset=\"{}\"/>\n"),
                 block.offset());
  block.add(data, count);
}

void fieldArray(fmt::memory_buffer& xml, AppendedBlock& block, const FieldArray& a) {
  if (!a.integer) {
    appendedArray(xml, block, "Float64", a.name, a.components, a.values.data(), a.values.size(),
                  a.componentNames);
    return;
  }
  std::vector<int32_t> v(a.values.size());
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<int32_t>(a.values[i]);
  appendedArray(xml, block, "Int32", a.name, a.components, v.data(), v.size(), a.componentNames);
}
}  // namespace

std::string vtuRawText(const SceneFrame& f) {
  AppendedBlock block;
  fmt::memory_buffer xml;  // with compiled formats: ~1 us for a small frame
  append(xml,
         "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt32\">\n"
         "  <UnstructuredGrid>\n"
         "    <FieldData>\n");
  // The time as field data too: readers that ignore the .pvd still see it.
  fmt::format_to(
      std::back_inserter(xml),
      FMT_COMPILE("      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                  "format=\"appended\" offset=\"{}\"/>\n"),
      block.offset());
  block.add(&f.t, 1);
  fmt::format_to(
      std::back_inserter(xml),
      FMT_COMPILE("      <Array type=\"String\" Name=\"part_names\" NumberOfTuples=\"{}\" "
                  "format=\"appended\" offset=\"{}\"/>\n"),
      f.partNames.size(), block.offset());
  block.addStrings(f.partNames);
  append(xml, "    </FieldData>\n");
  fmt::format_to(
      std::back_inserter(xml),
      FMT_COMPILE("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n      <PointData>\n"),
      f.points.size() / 3, f.numCells());
  for (const auto& a : f.pointData) fieldArray(xml, block, a);
  append(xml, "      </PointData>\n      <CellData>\n");
  for (const auto& a : f.cellData) fieldArray(xml, block, a);
  append(xml, "      </CellData>\n      <Points>\n");
  appendedArray(xml, block, "Float64", "Points", 3, f.points.data(), f.points.size());
  append(xml, "      </Points>\n      <Cells>\n");
  const std::vector<int64_t> conn(f.connectivity.begin(), f.connectivity.end());
  appendedArray(xml, block, "Int64", "connectivity", 1, conn.data(), conn.size());
  const std::vector<int64_t> offsets(f.offsets.begin(), f.offsets.end());
  appendedArray(xml, block, "Int64", "offsets", 1, offsets.data(), offsets.size());
  std::vector<uint8_t> types(f.shapes.size());
  for (size_t c = 0; c < types.size(); ++c) types[c] = static_cast<uint8_t>(f.shapes[c]);
  appendedArray(xml, block, "UInt8", "types", 1, types.data(), types.size());
  append(xml,
         "      </Cells>\n"
         "    </Piece>\n"
         "  </UnstructuredGrid>\n"
         "  <AppendedData encoding=\"raw\">\n   _");
  append(xml, block.bytes());
  append(xml, "\n  </AppendedData>\n</VTKFile>\n");
  return fmt::to_string(xml);
}

}  // namespace chute
