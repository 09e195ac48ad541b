#pragma once

#include <string>

namespace mpm
{
  /// fsync the file or folder @p path (its data, or its entries), so that
  /// it survives a crash of the machine, not only of the process.
  void
  flush_to_storage(const std::string &path);

  /// Write @p content to @p file_name via a temporary file that is flushed
  /// to storage, an atomic rename, and a flush of the folder: a crash at
  /// any moment leaves the old or the new content, both complete.
  void
  write_file_durably(const std::string &file_name, const std::string &content);
} // namespace mpm
