#include <mpm/io/atomic_files.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace mpm
{
  void
  flush_to_storage(const std::string &path)
  {
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0 || ::fsync(fd) != 0)
      {
        const int error = errno;
        if (fd >= 0)
          ::close(fd);
        throw std::runtime_error("cannot flush '" + path +
                                 "' to storage: " + std::strerror(error));
      }
    ::close(fd);
  }

  void
  write_file_atomically(const std::string &file_name,
                        const std::string &content,
                        const bool         durable)
  {
    const std::string tmp = file_name + ".tmp";
    {
      std::ofstream out(tmp);
      out << content;
      if (!out)
        throw std::runtime_error("Cannot write the file '" + tmp + "'");
    }
    if (durable)
      flush_to_storage(tmp);
    if (std::rename(tmp.c_str(), file_name.c_str()) != 0)
      throw std::runtime_error("Cannot rename '" + tmp + "' to '" + file_name +
                               "'");
    if (durable)
      {
        // the rename changed the folder's entries: flush the folder too
        const auto slash = file_name.find_last_of('/');
        flush_to_storage(slash == std::string::npos ? std::string(".") :
                         slash == 0                 ? std::string("/") :
                                                      file_name.substr(0, slash));
      }
  }
} // namespace mpm
