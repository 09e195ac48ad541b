#pragma once

#include <string>

/**
 * Free space of the file system that holds the output, for messages and
 * for the check before a checkpoint (p4est aborts the process when a
 * write fails, so a checkpoint must fit before it is begun).
 */
namespace mpm
{
  /// Bytes a non-privileged write may still use in the file system of
  /// @p path (or of its nearest existing parent); negative if unknown.
  double
  available_bytes(const std::string &path);

  /// " (the file system of 'path' has 12.5 MB free)", or "" if unknown.
  std::string
  free_space_note(const std::string &path);

  /**
   * "cannot write WHAT in 'FOLDER' (the file system of 'SPACE_OF' has 12.5
   * MB free): ", the start of every message of a failed write; the free
   * space is that of @p space_of, or of @p folder if it is "".
   */
  std::string
  cannot_write(const std::string &what,
               const std::string &folder,
               const std::string &space_of = "");

  /**
   * A RuntimeError unless @p needed_bytes fit into the file system of
   * @p path; @p keep, appended to the message, says what stays intact.
   */
  void
  require_space(const std::string &path,
                const double       needed_bytes,
                const std::string &keep);
} // namespace mpm
