#include "render/FrameXml.hpp"

#include <vtkDataCompressor.h>
#include <vtkLZ4DataCompressor.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkZLibDataCompressor.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

#include "render/FrameFile.hpp"

namespace chute::render {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw std::runtime_error(path + ": " + why + " (not a frame chute wrote)");
}

bool isCount(const char* text, double most) {
  if (!text || !*text) return false;
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  return *end == '\0' && v >= 0 && v <= most && v == std::floor(v);
}

bool oneOf(const char* text, std::initializer_list<const char*> allowed) {
  if (!text) return false;
  for (const char* a : allowed)
    if (std::strcmp(text, a) == 0) return true;
  return false;
}

bool blank(const char* text) {
  if (!text) return true;
  for (; *text; ++text)
    if (!std::isspace(static_cast<unsigned char>(*text))) return false;
  return true;
}

// A data array as VTK's XML reader trusts it: a known type, a name, a component count and a
// tuple count within bounds, a known format, an offset into the appended data.
void checkArray(vtkXMLDataElement* a, const std::string& path, bool allowString,
                bool needName = true) {
  const std::string where = std::string("<") + a->GetName() + " Name=\"" +
                            (a->GetAttribute("Name") ? a->GetAttribute("Name") : "") + "\">";
  if (!oneOf(a->GetAttribute("type"), {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32",
                                       "Int64", "UInt64", "Float32", "Float64"}) &&
      !(allowString && oneOf(a->GetAttribute("type"), {"String"})))
    fail(path, where + ": a data type VTK's reader does not take");
  // A field without a name would reach the messages that list fields as a null name.
  if (needName && blank(a->GetAttribute("Name"))) fail(path, where + ": no name");
  if (a->GetAttribute("NumberOfComponents") && !isCount(a->GetAttribute("NumberOfComponents"), 16))
    fail(path, where + ": NumberOfComponents not in 1 to 16");
  if (a->GetAttribute("NumberOfComponents") &&
      std::strtod(a->GetAttribute("NumberOfComponents"), nullptr) < 1)
    fail(path, where + ": NumberOfComponents not in 1 to 16");
  if (a->GetAttribute("NumberOfTuples") && !isCount(a->GetAttribute("NumberOfTuples"), 1e6))
    fail(path, where + ": NumberOfTuples beyond 1e6");
  const char* format = a->GetAttribute("format");
  // Inline base64 ("binary") chute never writes: appended raw data and ASCII are read.
  if (!oneOf(format, {"appended", "ascii"})) fail(path, where + ": not appended or ASCII data");
  if (std::strcmp(format, "appended") == 0) {
    if (!isCount(a->GetAttribute("offset"), 1e15)) fail(path, where + ": no offset");
    if (!blank(a->GetCharacterData())) fail(path, where + ": text in an appended array");
  }
  for (int i = 0; i < a->GetNumberOfNestedElements(); ++i)
    if (std::strcmp(a->GetNestedElement(i)->GetName(), "InformationKey") != 0)
      fail(path, where + ": holds <" + a->GetNestedElement(i)->GetName() + ">");
}

std::size_t typeSize(const char* type) {
  if (oneOf(type, {"Int8", "UInt8", "String"})) return 1;
  if (oneOf(type, {"Int16", "UInt16"})) return 2;
  if (oneOf(type, {"Int32", "UInt32", "Float32"})) return 4;
  return 8;
}

// The appended data as VTK's reader trusts it (a changed size in a block header ran it out of
// memory or past the end of the file): every appended array's header -- a byte count, or for
// compressed data the number of blocks, their size, the last block's size and each block's
// compressed size -- within the file, and the bytes it announces those the array must hold
// (`count` values of `size` bytes; count < 0: not known from the header, as connectivity).
class AppendedData {
 public:
  AppendedData(const std::string& bytes, const std::string& path, bool compressed,
               std::size_t header)
      : bytes_(bytes), path_(path), compressed_(compressed), header_(header) {
    const std::size_t tag = bytes.find("<AppendedData");
    if (tag == std::string::npos) return;
    std::size_t at = bytes.find('>', tag);
    if (at == std::string::npos) fail(path, "<AppendedData> not closed");
    ++at;
    while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
    if (at >= bytes.size() || bytes[at] != '_')
      fail(path, "<AppendedData> does not start with '_'");
    start_ = at + 1;
  }

  // The bytes of a checked appended array, uncompressed (at most `most`; the compressor's own
  // decompression is bounded by the sizes checked in check()).
  std::string payload(vtkXMLDataElement* a, const char* compressor, std::size_t most) const {
    std::size_t at =
        start_ + static_cast<std::size_t>(std::strtod(a->GetAttribute("offset"), nullptr));
    const std::string where = "<Array Name=\"part_names\">";
    if (!compressed_) {
      const std::size_t n = read(at, where);
      return bytes_.substr(at, std::min(n, most));
    }
    const std::size_t blocks = read(at, where), size = read(at, where), last = read(at, where);
    std::vector<std::size_t> packed(blocks);
    for (auto& c : packed) c = read(at, where);
    vtkSmartPointer<vtkDataCompressor> z;
    if (oneOf(compressor, {"vtkLZ4DataCompressor"}))
      z = vtkSmartPointer<vtkLZ4DataCompressor>::New();
    if (oneOf(compressor, {"vtkZLibDataCompressor"}))
      z = vtkSmartPointer<vtkZLibDataCompressor>::New();
    if (!z) return {};
    std::string out;
    for (std::size_t b = 0; b < blocks && out.size() < most; ++b) {
      const std::size_t n = b + 1 == blocks && last != 0 ? last : size;
      std::string block(n, '\0');
      const std::size_t got =
          z->Uncompress(reinterpret_cast<const unsigned char*>(bytes_.data() + at), packed[b],
                        reinterpret_cast<unsigned char*>(block.data()), n);
      if (got != n) fail(path_, where + ": its data do not decompress");
      out += block;
      at += packed[b];
    }
    return out.substr(0, most);
  }

  void check(vtkXMLDataElement* a, double count, const std::string& where) const {
    if (start_ == std::string::npos) fail(path_, where + ": appended, with no <AppendedData>");
    const double offset = std::strtod(a->GetAttribute("offset"), nullptr);
    std::size_t at = start_ + static_cast<std::size_t>(offset);
    const std::size_t want =
        count < 0 ? std::string::npos
                  : static_cast<std::size_t>(count) * typeSize(a->GetAttribute("type"));
    if (!compressed_) {
      const std::size_t n = read(at, where);
      if ((want != std::string::npos && n != want) || n > bytes_.size() - at)
        fail(path_, where + ": its header announces " + std::to_string(n) + " bytes" +
                        (want != std::string::npos ? ", it needs " + std::to_string(want) : "") +
                        ", " + std::to_string(bytes_.size() - at) + " are left");
      return;
    }
    const std::size_t blocks = read(at, where), size = read(at, where), last = read(at, where);
    if (blocks > (bytes_.size() - at) / header_ || size > (std::size_t{1} << 31) || last > size ||
        (blocks > 0 && size == 0))
      fail(path_, where + ": a compressed header that does not fit the file");
    const std::size_t total = blocks == 0 ? 0 : (blocks - 1) * size + (last == 0 ? size : last);
    if ((want != std::string::npos && total != want) || total > (std::size_t{1} << 32))
      fail(path_, where + ": its blocks hold " + std::to_string(total) + " bytes" +
                      (want != std::string::npos ? ", it needs " + std::to_string(want) : ""));
    std::size_t packed = 0;
    for (std::size_t b = 0; b < blocks; ++b) packed += read(at, where);
    if (packed > bytes_.size() - at)
      fail(path_, where + ": its blocks run past the end of the file");
  }

 private:
  std::size_t read(std::size_t& at, const std::string& where) const {
    if (at > bytes_.size() || bytes_.size() - at < header_)
      fail(path_, where + ": its data header runs past the end of the file");
    std::uint64_t v = 0;
    if (header_ == 4) {
      std::uint32_t w = 0;
      std::memcpy(&w, bytes_.data() + at, 4);
      v = w;
    } else {
      std::memcpy(&v, bytes_.data() + at, 8);
    }
    at += header_;
    return static_cast<std::size_t>(std::min<std::uint64_t>(v, std::uint64_t{1} << 62));
  }

  const std::string& bytes_;
  const std::string& path_;
  bool compressed_;
  std::size_t header_;
  std::size_t start_ = std::string::npos;
};

}  // namespace

// The structure of a frame as chute writes it (docs/output.md), checked on its XML before VTK's
// reader builds anything from it: the reader trusts what it is given (an unknown data type in
// <FieldData>, or text inside <Cells>, crashed it).
std::vector<std::string> checkFrameXml(const std::string& bytes, const std::string& path) {
  std::istringstream in(bytes);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&in);
  if (!parser->Parse()) fail(path, "not a VTK XML file");
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!root || std::strcmp(root->GetName(), "VTKFile") != 0) fail(path, "no <VTKFile>");
  if (!oneOf(root->GetAttribute("type"), {"UnstructuredGrid"}))
    fail(path, "not an unstructured grid");
  if (!oneOf(root->GetAttribute("version"), {"0.1", "1.0", "2.0", "2.1", "2.2"}))
    fail(path, "a VTK file version this reader does not take");
  if (!oneOf(root->GetAttribute("byte_order"), {"LittleEndian"}))
    fail(path, "not little-endian data (chute writes LittleEndian)");
  if (root->GetAttribute("header_type") &&
      !oneOf(root->GetAttribute("header_type"), {"UInt32", "UInt64"}))
    fail(path, "an unknown header type");
  if (root->GetAttribute("compressor") &&
      !oneOf(root->GetAttribute("compressor"),
             {"vtkZLibDataCompressor", "vtkLZ4DataCompressor", "vtkLZMADataCompressor"}))
    fail(path, "an unknown compressor");
  vtkXMLDataElement* grid = nullptr;
  for (int i = 0; i < root->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = root->GetNestedElement(i);
    if (std::strcmp(e->GetName(), "UnstructuredGrid") == 0 && !grid)
      grid = e;
    else if (std::strcmp(e->GetName(), "AppendedData") == 0 &&
             oneOf(e->GetAttribute("encoding"), {"raw"}))
      ;  // its headers are checked below, array by array
    else
      fail(path, std::string("<VTKFile> holds <") + e->GetName() + ">");
  }
  if (!grid || !blank(grid->GetCharacterData())) fail(path, "no <UnstructuredGrid>");
  vtkXMLDataElement* piece = nullptr;
  for (int i = 0; i < grid->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = grid->GetNestedElement(i);
    if (std::strcmp(e->GetName(), "FieldData") == 0) {
      if (!blank(e->GetCharacterData())) fail(path, "text in <FieldData>");
      for (int k = 0; k < e->GetNumberOfNestedElements(); ++k)
        checkArray(e->GetNestedElement(k), path, true);
    } else if (std::strcmp(e->GetName(), "Piece") == 0 && !piece) {
      piece = e;
    } else {
      fail(path, std::string("<UnstructuredGrid> holds <") + e->GetName() + ">");
    }
  }
  if (!piece) fail(path, "no <Piece>");
  // Counts bounded before VTK sizes its arrays by them (about 1 GB at most).
  if (!isCount(piece->GetAttribute("NumberOfPoints"), kMaxFramePoints) ||
      !isCount(piece->GetAttribute("NumberOfCells"), kMaxFrameCells))
    fail(path, "NumberOfPoints or NumberOfCells missing or beyond " +
                   std::to_string(static_cast<long long>(kMaxFramePoints)) + " and " +
                   std::to_string(static_cast<long long>(kMaxFrameCells)));
  if (!blank(piece->GetCharacterData())) fail(path, "text in <Piece>");
  bool points = false, cells = false;
  for (int i = 0; i < piece->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = piece->GetNestedElement(i);
    const std::string name = e->GetName();
    if (!blank(e->GetCharacterData())) fail(path, "text in <" + name + ">");
    if (name != "PointData" && name != "CellData" && name != "Points" && name != "Cells")
      fail(path, "<Piece> holds <" + name + ">");
    for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) {
      vtkXMLDataElement* a = e->GetNestedElement(k);
      if (std::strcmp(a->GetName(), "DataArray") != 0)
        fail(path, "<" + name + "> holds <" + a->GetName() + ">");
      checkArray(a, path, false, name != "Points");
    }
    if (name == "Points") {
      if (points || e->GetNumberOfNestedElements() != 1 ||
          !oneOf(e->GetNestedElement(0)->GetAttribute("NumberOfComponents"), {"3"}) ||
          !oneOf(e->GetNestedElement(0)->GetAttribute("type"), {"Float32", "Float64"}))
        fail(path, "<Points> is not one array of 3 real components");
      points = true;
    }
    if (name == "Cells") {
      std::vector<std::string> names;
      for (int k = 0; k < e->GetNumberOfNestedElements(); ++k) {
        const char* n = e->GetNestedElement(k)->GetAttribute("Name");
        names.push_back(n ? n : "");
        if (oneOf(e->GetNestedElement(k)->GetAttribute("type"), {"Float32", "Float64"}))
          fail(path, "<Cells> with a real-valued array");
      }
      std::sort(names.begin(), names.end());
      if (cells || names != std::vector<std::string>{"connectivity", "offsets", "types"})
        fail(path, "<Cells> is not connectivity, offsets and types");
      cells = true;
    }
  }
  if (!points || !cells) fail(path, "no <Points> or <Cells>");

  const AppendedData data(bytes, path, root->GetAttribute("compressor") != nullptr,
                          oneOf(root->GetAttribute("header_type"), {"UInt64"}) ? 8 : 4);
  const double nPoints = std::strtod(piece->GetAttribute("NumberOfPoints"), nullptr);
  const double nCells = std::strtod(piece->GetAttribute("NumberOfCells"), nullptr);
  auto each = [&](vtkXMLDataElement* parent, double tuples) {
    for (int k = 0; k < parent->GetNumberOfNestedElements(); ++k) {
      vtkXMLDataElement* a = parent->GetNestedElement(k);
      if (!oneOf(a->GetAttribute("format"), {"appended"})) continue;
      const char* name = a->GetAttribute("Name");
      const double components = a->GetAttribute("NumberOfComponents")
                                    ? std::strtod(a->GetAttribute("NumberOfComponents"), nullptr)
                                    : 1.0;
      double count = tuples < 0 ? -1.0 : tuples * components;
      if (tuples == -2.0)  // field data: its own tuple count (strings: not known)
        count = oneOf(a->GetAttribute("type"), {"String"}) || !a->GetAttribute("NumberOfTuples")
                    ? -1.0
                    : std::strtod(a->GetAttribute("NumberOfTuples"), nullptr) * components;
      if (oneOf(name, {"connectivity"})) count = -1.0;
      data.check(a, count, std::string("<DataArray Name=\"") + (name ? name : "") + "\">");
    }
  };
  for (int i = 0; i < grid->GetNumberOfNestedElements(); ++i)
    if (std::strcmp(grid->GetNestedElement(i)->GetName(), "FieldData") == 0)
      each(grid->GetNestedElement(i), -2.0);
  for (int i = 0; i < piece->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = piece->GetNestedElement(i);
    const std::string name = e->GetName();
    each(e, name == "CellData" || name == "Cells" ? nCells : nPoints);
  }
  // The part names (the legend of --color part), decoded here: VTK's reader of string arrays
  // reads past its buffer when the strings are fewer than their count.
  std::vector<std::string> names;
  for (int i = 0; i < grid->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* f = grid->GetNestedElement(i);
    if (std::strcmp(f->GetName(), "FieldData") != 0) continue;
    for (int k = 0; k < f->GetNumberOfNestedElements(); ++k) {
      vtkXMLDataElement* a = f->GetNestedElement(k);
      if (!oneOf(a->GetAttribute("Name"), {"part_names"}) ||
          !oneOf(a->GetAttribute("format"), {"appended"}) ||
          !oneOf(a->GetAttribute("type"), {"String"}))
        continue;
      const std::string text = data.payload(a, root->GetAttribute("compressor"), 1u << 20);
      const double count = a->GetAttribute("NumberOfTuples")
                               ? std::strtod(a->GetAttribute("NumberOfTuples"), nullptr)
                               : 0.0;
      std::size_t from = 0;
      while (names.size() < count && from < text.size()) {
        const std::size_t end = text.find('\0', from);
        names.push_back(
            text.substr(from, end == std::string::npos ? std::string::npos : end - from));
        if (end == std::string::npos) break;
        from = end + 1;
      }
    }
  }
  return names;
}

// The frame's bytes with its <FieldData> blanked (the same length: offsets into the appended data
// stay right), so that VTK's reader never reads its string array.
std::string withoutFieldData(std::string bytes) {
  const std::size_t data = bytes.find("<AppendedData");
  const std::size_t open = bytes.find("<FieldData");
  if (open == std::string::npos || open > data) return bytes;
  const std::size_t close = bytes.find("</FieldData>", open);
  if (close == std::string::npos || close > data) return bytes;
  for (std::size_t i = open; i < close + 12; ++i)
    if (bytes[i] != '\n') bytes[i] = ' ';
  return bytes;
}

}  // namespace chute::render
