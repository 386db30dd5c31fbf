#pragma once
// The XML of a frame, checked before VTK's reader builds anything from it: VTK 9.1's reader trusts
// what it is given (an unknown data type in <FieldData> and stray text inside <Cells> crashed
// it; a changed byte count in an appended block header ran it out of memory or past the end of
// the file). The structure must be that of a frame chute writes (docs/output.md): one piece of
// an unstructured grid, known data types, appended raw data (or ASCII), every appended array's
// header within the file and announcing the bytes the array needs, counts bounded
// (FrameFile.hpp).
#include <string>
#include <vector>

namespace chute::render {

// Throws std::runtime_error "path: reason" for a frame that is not of that structure; returns
// the part names of its <FieldData> (decoded here: VTK's reader of string arrays reads past its
// buffer when the strings are fewer than their count).
std::vector<std::string> checkFrameXml(const std::string& bytes, const std::string& path);

// The frame's bytes with its <FieldData> blanked (the same length: offsets into the appended data
// stay right), so that VTK's reader never reads its string array.
std::string withoutFieldData(std::string bytes);

}  // namespace chute::render
