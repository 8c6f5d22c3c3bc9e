// The two parts of a path as the kernel splits it: the folder a name is
// looked up in and the last name, for output checks and temporaries that
// must land beside their file.
#ifndef DEXMILL_PLATFORM_OS_PATH_NAME_H
#define DEXMILL_PLATFORM_OS_PATH_NAME_H

#include <string>

namespace dexmill {

// The folder of `path` ("." for a bare name, "/" for a file in the root).
inline std::string folder_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// The last name of `path` (all of it when it has no '/').
inline std::string name_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace dexmill

#endif
