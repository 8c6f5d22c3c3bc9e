// Reading a whole input file into memory (design meshes and images), with a
// size limit that is an error, never a silent cut.
#ifndef DEXMILL_PLATFORM_OS_READ_FILE_H
#define DEXMILL_PLATFORM_OS_READ_FILE_H

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dexmill {

enum class ReadFile : uint8_t { kOk, kTooLarge, kIoError };

// The bytes of `path`. kTooLarge when it holds more than max_bytes (*err:
// "PATH: error: larger than N MB"); kIoError when it cannot be opened or
// read (*err: "dexmill: error: cannot read 'PATH': reason").
ReadFile read_whole_file(const std::string& path, std::size_t max_bytes, std::vector<unsigned char>* out,
                         std::string* err);

}  // namespace dexmill

#endif
