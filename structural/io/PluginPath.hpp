#pragma once
// Where chute looks for one of its plugins (the gmsh plugin, the render plugin): the path the
// environment variable names, else the file next to the running executable, else the build
// tree's (where a test or a script runs an executable from elsewhere).
#include <string>

namespace chute {

std::string pluginPath(const char* environmentVariable, const char* fileName,
                       const char* buildTreePath);

}  // namespace chute
