#pragma once

#include <deal.II/grid/tria.h>

#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

/**
 * Checkpoint files (doc/checkpointing.md). A checkpoint is one folder
 * Output/Directory/checkpoint/step-NNNNNNNN/ holding the triangulation with
 * the particles attached (p4est's files in 2D/3D, a boost archive and a
 * particle table in 1D), the solver state (state.txt), the parameters of
 * the run (parameters.prm) and a copy of the statistics file. The file
 * checkpoint/latest.txt names the latest complete folder; it is replaced
 * by a rename only after every file of a new folder is written and listed
 * with its size and CRC-32 in the folder's manifest.txt; all but the
 * previous latest folder are removed only after that, so a run killed at
 * any moment leaves a usable checkpoint behind, and a restart verifies
 * every file before it loads anything (and may fall back to the previous
 * checkpoint when the latest is damaged).
 */
namespace mpm
{
  namespace checkpoint
  {
    /// Everything besides grid and particles that the next step, the
    /// output and the statistics depend on.
    struct SolverState
    {
      unsigned int       dimension          = 0;
      unsigned int       n_ranks            = 0; ///< of the run that wrote it
      unsigned int       n_properties       = 0; ///< per particle
      unsigned long long n_particles        = 0;
      double             time               = 0;
      unsigned int       step               = 0;
      double             last_dt            = 0;
      double             stable_dt          = 0;
      double             min_nodal_mass     = 0;
      double             next_output_time   = 0;
      unsigned int       last_output_step   = 0;
      unsigned int       n_outputs          = 0;
      unsigned int       n_global_sorts     = 0;
      unsigned long long n_filter_fallbacks = 0;
      std::string        grid_fingerprint;
      /// Mass removed so far, per rank of the run that wrote it (so that a
      /// restart on as many ranks sums it in the same order).
      std::vector<double> removed_mass;
      /// The ParaView series so far: (time, file) of every output.
      std::vector<std::pair<double, std::string>> particle_records,
        grid_records;
      /// Rows of the Test summary file so far.
      std::vector<std::string> summary_rows;

      /// Exact text form (doubles with 17 significant digits).
      void
      write(std::ostream &out) const;
      /// Throws std::runtime_error naming @p file_name if damaged.
      void
      read(std::istream &in, const std::string &file_name);
    };

    /// Output/Directory/checkpoint
    std::string
    root(const std::string &output_directory);

    /// The latest complete checkpoint folder (a path), or "" if there is
    /// none. Rank 0 only (file system).
    std::string
    latest(const std::string &output_directory);

    /// Rank 0: an empty folder for the checkpoint of @p step (leftovers of
    /// an interrupted write of the same step are removed; the latest
    /// complete checkpoint is never touched). Returns its path.
    std::string
    begin(const std::string &output_directory, const unsigned int step);

    /// Rank 0, after every file of @p folder is written: write its
    /// manifest, make it the latest (atomic rename of latest.txt) and
    /// remove every other folder but the previous latest (the two latest
    /// complete checkpoints are kept).
    void
    commit(const std::string &output_directory, const std::string &folder);

    /// Rank 0: latest.txt names @p folder (an atomic rename).
    void
    set_latest(const std::string &output_directory, const std::string &folder);

    /// Rank 0: @p folder/manifest.txt, the size and CRC-32 of every other
    /// file of the folder.
    void
    write_manifest(const std::string &folder);

    /// Rank 0: "" if @p folder exists, has its manifest, and every file
    /// the manifest lists has its size and CRC-32; else a message naming
    /// the first damaged or missing file. Nothing else is read.
    std::string
    verify(const std::string &folder);

    /// Rank 0: the checkpoint folders other than the latest, the newest
    /// (highest step) first.
    std::vector<std::string>
    earlier_checkpoints(const std::string &output_directory);

    /// Total size in bytes of the files in @p folder.
    unsigned long long
    folder_size(const std::string &folder);

    /**
     * Whether a parameter (its path "Subsection/Entry" as in the PRM text)
     * must be the same on restart: everything except Output/...,
     * Checkpointing/..., Load balancing/..., Time stepping/End time and
     * Time stepping/Maximum number of steps.
     */
    bool
    is_critical(const std::string &path);

    /// "Subsection/Entry" -> value of every entry of a ShortPRM text.
    std::map<std::string, std::string>
    parse_short_prm(const std::string &text);

    /**
     * Compare the critical entries of two ShortPRM texts: "" if they
     * agree, else a message naming the first parameter that differs, both
     * values and @p checkpoint_file.
     */
    std::string
    compare_parameters(const std::string &saved,
                       const std::string &now,
                       const std::string &checkpoint_file);

    /// Hash of the coarse mesh (cells, vertices, boundary ids), the same
    /// on every rank: a changed mesh file is detected on restart.
    template <int dim>
    std::string
    coarse_mesh_fingerprint(const dealii::Triangulation<dim> &tria);

    /// The whole content of a file (throws std::runtime_error).
    std::string
    read_file(const std::string &file_name);
  } // namespace checkpoint
} // namespace mpm
