#include <mpm/io/disk_space.h>
#include <mpm/utilities/input_error.h>

#include <filesystem>
#include <sstream>

namespace mpm
{
  namespace fs = std::filesystem;

  double
  available_bytes(const std::string &path)
  {
    fs::path        p = path.empty() ? fs::path(".") : fs::path(path);
    std::error_code error;
    while (!p.empty() && !fs::exists(p, error))
      p = p.parent_path();
    if (p.empty())
      p = ".";
    const auto space = fs::space(p, error);
    return error ? -1. : double(space.available);
  }

  namespace
  {
    std::string
    megabytes(const double bytes)
    {
      std::ostringstream s;
      s.precision(3);
      s << bytes / 1e6 << " MB";
      return s.str();
    }
  } // namespace

  std::string
  free_space_note(const std::string &path)
  {
    const double free = available_bytes(path);
    if (free < 0)
      return "";
    return " (the file system of '" + path + "' has " + megabytes(free) +
           " free)";
  }

  std::string
  cannot_write(const std::string &what,
               const std::string &folder,
               const std::string &space_of)
  {
    return "cannot write " + what + " in '" + folder + "'" +
           free_space_note(space_of.empty() ? folder : space_of) + ": ";
  }

  void
  require_space(const std::string &path,
                const double       needed_bytes,
                const std::string &keep)
  {
    const double free = available_bytes(path);
    if (free >= 0 && free < needed_bytes)
      throw RuntimeError("no room on the disk: about " +
                         megabytes(needed_bytes) + " are needed in '" + path +
                         "', the file system has " + megabytes(free) +
                         " free. " + keep);
  }
} // namespace mpm
