#include "dynamap/robotio/AtomicFile.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace dynamap::robotio {

namespace fs = std::filesystem;

std::string TemporaryPathFor(const std::string& file) {
  static std::atomic<unsigned> counter{0};
  const fs::path target(file);
  // Keep the extension: some writers (OpenCV) choose the format by it.
  const std::string name = "." + target.stem().string() + ".tmp" + std::to_string(::getpid()) +
                           "_" + std::to_string(counter++) + target.extension().string();
  return (target.parent_path() / name).string();
}

Status WriteFileAtomically(const std::string& file,
                           const std::function<bool(const std::string&)>& write) {
  const std::string temporary = TemporaryPathFor(file);
  if (!write(temporary)) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return Error{file + ": could not be written"};
  }
  if (std::rename(temporary.c_str(), file.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return Error{file + ": could not be written (" + reason + ")"};
  }
  return Ok{};
}

Status WriteFileAtomically(const std::string& file, const std::string& contents) {
  return WriteFileAtomically(file, [&contents](const std::string& path) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    return static_cast<bool>(out);
  });
}

}  // namespace dynamap::robotio
