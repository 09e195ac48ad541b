#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <mpm/io/atomic_files.h>
#include <mpm/io/checkpoint.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <boost/crc.hpp>

namespace mpm
{
  namespace checkpoint
  {
    namespace fs = std::filesystem;

    namespace
    {
      const char *format_tag = "mpm-checkpoint 1";

      std::string
      trim(const std::string &s)
      {
        const auto b = s.find_first_not_of(" \t\r");
        if (b == std::string::npos)
          return "";
        const auto e = s.find_last_not_of(" \t\r");
        return s.substr(b, e - b + 1);
      }

      std::string
      without_blanks(const std::string &s)
      {
        std::string r;
        for (const char c : s)
          if (c != ' ' && c != '\t')
            r += c;
        return r;
      }

      /// FNV-1a, 64 bit.
      struct Hash
      {
        std::uint64_t h = 1469598103934665603ull;
        void
        add(const void *data, const std::size_t n)
        {
          const auto *b = static_cast<const unsigned char *>(data);
          for (std::size_t i = 0; i < n; ++i)
            {
              h ^= b[i];
              h *= 1099511628211ull;
            }
        }
        template <typename T>
        void
        add(const T &value)
        {
          add(&value, sizeof(T));
        }
      };
    } // namespace

    // ------------------------------------------------------------ state
    void
    SolverState::write(std::ostream &out) const
    {
      out << format_tag << '\n' << std::setprecision(17);
      out << "dimension " << dimension << '\n'
          << "n_ranks " << n_ranks << '\n'
          << "n_properties " << n_properties << '\n'
          << "n_particles " << n_particles << '\n'
          << "time " << time << '\n'
          << "step " << step << '\n'
          << "last_dt " << last_dt << '\n'
          << "stable_dt " << stable_dt << '\n'
          << "min_nodal_mass " << min_nodal_mass << '\n'
          << "next_output_time " << next_output_time << '\n'
          << "last_output_step " << last_output_step << '\n'
          << "n_outputs " << n_outputs << '\n'
          << "n_global_sorts " << n_global_sorts << '\n'
          << "n_filter_fallbacks " << n_filter_fallbacks << '\n'
          << "grid_fingerprint " << grid_fingerprint << '\n'
          << "removed_mass " << removed_mass.size();
      for (const double m : removed_mass)
        out << ' ' << m;
      out << '\n';
      for (const auto *records : {&particle_records, &grid_records})
        {
          out << (records == &particle_records ? "particle_records " :
                                                 "grid_records ")
              << records->size() << '\n';
          for (const auto &[t, name] : *records)
            out << t << ' ' << name << '\n';
        }
      out << "summary_rows " << summary_rows.size() << '\n';
      for (const auto &r : summary_rows)
        out << r << '\n';
      out << "end\n";
    }

    void
    SolverState::read(std::istream &in, const std::string &file_name)
    {
      auto fail = [&](const std::string &what) {
        throw std::runtime_error("the checkpoint file '" + file_name +
                                 "' is damaged (" + what + ")");
      };
      std::string line;
      if (!std::getline(in, line) || line != format_tag)
        fail("it does not start with '" + std::string(format_tag) + "'");
      auto expect = [&](const std::string &key, auto &value) {
        std::string k;
        if (!(in >> k) || k != key)
          fail("expected '" + key + "'");
        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, double>)
          {
            // strtod reads inf and nan as well
            std::string text;
            in >> text;
            char *end = nullptr;
            value     = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0')
              fail("bad value of '" + key + "'");
          }
        else if (!(in >> value))
          fail("bad value of '" + key + "'");
      };
      expect("dimension", dimension);
      expect("n_ranks", n_ranks);
      expect("n_properties", n_properties);
      expect("n_particles", n_particles);
      expect("time", time);
      expect("step", step);
      expect("last_dt", last_dt);
      expect("stable_dt", stable_dt);
      expect("min_nodal_mass", min_nodal_mass);
      expect("next_output_time", next_output_time);
      expect("last_output_step", last_output_step);
      expect("n_outputs", n_outputs);
      expect("n_global_sorts", n_global_sorts);
      expect("n_filter_fallbacks", n_filter_fallbacks);
      expect("grid_fingerprint", grid_fingerprint);
      std::size_t n = 0;
      expect("removed_mass", n);
      removed_mass.resize(n);
      for (auto &m : removed_mass)
        {
          std::string text;
          in >> text;
          m = std::strtod(text.c_str(), nullptr);
        }
      for (auto *records : {&particle_records, &grid_records})
        {
          expect(records == &particle_records ? "particle_records" :
                                                "grid_records",
                 n);
          records->resize(n);
          for (auto &[t, name] : *records)
            {
              std::string text;
              in >> text;
              t = std::strtod(text.c_str(), nullptr);
              std::getline(in, name);
              name = trim(name);
            }
        }
      expect("summary_rows", n);
      std::getline(in, line);
      summary_rows.resize(n);
      for (auto &r : summary_rows)
        std::getline(in, r);
      if (!(in >> line) || line != "end")
        fail("it is incomplete");
    }

    // ------------------------------------------------------------ files
    std::string
    root(const std::string &output_directory)
    {
      return output_directory + "/checkpoint";
    }

    std::string
    latest(const std::string &output_directory)
    {
      const std::string pointer = root(output_directory) + "/latest.txt";
      std::ifstream     in(pointer);
      std::string       name;
      if (!in || !std::getline(in, name) || trim(name).empty())
        return "";
      return root(output_directory) + "/" + trim(name);
    }

    std::string
    begin(const std::string &output_directory, const unsigned int step)
    {
      std::ostringstream name;
      name << "step-" << std::setw(8) << std::setfill('0') << step;
      std::string folder = root(output_directory) + "/" + name.str();
      // A run started anew (Resume computation = false) over the
      // checkpoints of an earlier one may reach a step whose folder is the
      // latest complete checkpoint: that one stays until the new one is
      // complete, so the new one gets another name.
      while (folder == latest(output_directory))
        folder += "-new";
      fs::remove_all(folder);
      fs::create_directories(folder);
      return folder;
    }

    namespace
    {
      /// Size and CRC-32 of a file, read in blocks.
      std::pair<unsigned long long, std::uint32_t>
      size_and_crc(const std::string &file_name)
      {
        std::ifstream in(file_name, std::ios::binary);
        if (!in)
          throw std::runtime_error("cannot read the file '" + file_name + "'");
        boost::crc_32_type crc;
        std::vector<char>  block(1 << 20);
        unsigned long long size = 0;
        while (in)
          {
            in.read(block.data(), block.size());
            crc.process_bytes(block.data(), in.gcount());
            size += in.gcount();
          }
        return {size, crc.checksum()};
      }

      const char *manifest_header = "mpm checkpoint manifest 1";
    } // namespace

    void
    write_manifest(const std::string &folder)
    {
      std::vector<std::string> files;
      for (const auto &entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file() &&
            entry.path().filename() != "manifest.txt")
          files.push_back(fs::relative(entry.path(), folder).string());
      std::sort(files.begin(), files.end());
      std::ostringstream text;
      text << manifest_header << '\n';
      for (const auto &f : files)
        {
          const auto [size, crc] = size_and_crc(folder + "/" + f);
          text << std::hex << std::setw(8) << std::setfill('0') << crc
               << std::dec << ' ' << size << ' ' << f << '\n';
        }
      text << "end\n";
      write_file_atomically(folder + "/manifest.txt", text.str());
    }

    std::string
    verify(const std::string &folder)
    {
      if (!fs::is_directory(folder))
        return "the checkpoint folder '" + folder +
               "' (named by latest.txt) does not exist";
      const std::string manifest = folder + "/manifest.txt";
      std::ifstream     in(manifest);
      std::string       line;
      if (!in || !std::getline(in, line) || line != manifest_header)
        return "the checkpoint '" + folder +
               "' has no readable manifest.txt (it is incomplete or damaged)";
      bool complete = false;
      while (std::getline(in, line))
        {
          if (line == "end")
            {
              complete = true;
              break;
            }
          std::istringstream row(line);
          std::string        crc_text, name;
          unsigned long long size = 0;
          if (!(row >> crc_text >> size) || !std::getline(row >> std::ws, name))
            return "the checkpoint file '" + manifest + "' is damaged (line '" +
                   line + "')";
          const std::string file = folder + "/" + name;
          std::error_code   error;
          if (!fs::is_regular_file(file, error))
            return "the checkpoint file '" + file + "' is missing";
          const auto [actual_size, crc] = size_and_crc(file);
          std::ostringstream actual_crc;
          actual_crc << std::hex << std::setw(8) << std::setfill('0') << crc;
          if (actual_size != size)
            return "the checkpoint file '" + file +
                   "' is damaged: " + std::to_string(actual_size) + " bytes, " +
                   std::to_string(size) + " when it was written";
          if (actual_crc.str() != crc_text)
            return "the checkpoint file '" + file +
                   "' is damaged: its CRC-32 is " + actual_crc.str() + ", " +
                   crc_text + " when it was written";
        }
      if (!complete)
        return "the checkpoint file '" + manifest + "' is incomplete";
      return "";
    }

    std::vector<std::string>
    earlier_checkpoints(const std::string &output_directory)
    {
      const std::string        dir = root(output_directory);
      const std::string        now = latest(output_directory);
      std::vector<std::string> out;
      std::error_code          error;
      if (!fs::is_directory(dir, error))
        return out;
      for (const auto &entry : fs::directory_iterator(dir))
        if (entry.is_directory() && entry.path().string() != now &&
            entry.path().filename().string().rfind("step-", 0) == 0)
          out.push_back(entry.path().string());
      // step-NNNNNNNN sorts by step; the newest first
      std::sort(out.rbegin(), out.rend());
      return out;
    }

    void
    set_latest(const std::string &output_directory, const std::string &folder)
    {
      write_file_atomically(root(output_directory) + "/latest.txt",
                            fs::path(folder).filename().string() + "\n",
                            true);
    }

    void
    commit(const std::string &output_directory, const std::string &folder)
    {
      const std::string dir = root(output_directory);
      write_manifest(folder);
      const std::string previous = latest(output_directory);
      // Every file of the new checkpoint reaches the storage device before
      // latest.txt names it, so a crash of the machine (not only of the
      // process) leaves either the old or the complete new checkpoint.
      for (const auto &entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
          flush_to_storage(entry.path().string());
      flush_to_storage(folder);
      flush_to_storage(dir);
      // The commit point: rename() replaces latest.txt atomically.
      set_latest(output_directory, folder);
      for (const auto &entry : fs::directory_iterator(dir))
        if (entry.is_directory() &&
            entry.path().filename() != fs::path(folder).filename() &&
            entry.path().string() != previous)
          fs::remove_all(entry.path());
    }

    unsigned long long
    folder_size(const std::string &folder)
    {
      unsigned long long n = 0;
      for (const auto &entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file())
          n += entry.file_size();
      return n;
    }

    std::string
    read_file(const std::string &file_name)
    {
      std::ifstream in(file_name, std::ios::binary);
      if (!in)
        throw std::runtime_error("cannot read the file '" + file_name + "'");
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }

    // ------------------------------------------------------- parameters
    bool
    is_critical(const std::string &path)
    {
      auto starts = [&](const std::string &prefix) {
        return path.compare(0, prefix.size(), prefix) == 0;
      };
      return !(starts("Output/") || starts("Checkpointing/") ||
               starts("Load balancing/") || path == "Time stepping/End time" ||
               path == "Time stepping/Maximum number of steps");
    }

    std::map<std::string, std::string>
    parse_short_prm(const std::string &text)
    {
      std::map<std::string, std::string> entries;
      std::vector<std::string>           sections;
      std::istringstream                 in(text);
      std::string                        line;
      while (std::getline(in, line))
        {
          line = trim(line);
          if (line.empty() || line[0] == '#')
            continue;
          if (line.compare(0, 11, "subsection ") == 0)
            sections.push_back(trim(line.substr(11)));
          else if (line == "end")
            {
              if (!sections.empty())
                sections.pop_back();
            }
          else if (line.compare(0, 4, "set ") == 0)
            {
              const auto  eq   = line.find('=');
              std::string path = "";
              for (const auto &s : sections)
                path += s + "/";
              if (eq == std::string::npos)
                entries[path + trim(line.substr(4))] = "";
              else
                entries[path + trim(line.substr(4, eq - 4))] =
                  trim(line.substr(eq + 1));
            }
        }
      return entries;
    }

    std::string
    compare_parameters(const std::string &saved_text,
                       const std::string &now_text,
                       const std::string &checkpoint_file)
    {
      const auto saved    = parse_short_prm(saved_text);
      const auto now      = parse_short_prm(now_text);
      auto       describe = [](const std::map<std::string, std::string> &m,
                         const std::string                        &k) {
        const auto i = m.find(k);
        return i == m.end() ? std::string("not present") :
                                    "'" + i->second + "'";
      };
      std::vector<std::string> keys;
      for (const auto &[k, v] : saved)
        keys.push_back(k);
      for (const auto &[k, v] : now)
        if (saved.find(k) == saved.end())
          keys.push_back(k);
      // Dimension and Number of bodies first: they explain the rest.
      for (const std::string first : {"Number of bodies", "Dimension"})
        for (auto &k : keys)
          if (k == first)
            {
              std::swap(k, keys.front());
              break;
            }
      for (const auto &k : keys)
        {
          if (!is_critical(k))
            continue;
          const auto a = saved.find(k), b = now.find(k);
          if (a != saved.end() && b != now.end() &&
              without_blanks(a->second) == without_blanks(b->second))
            continue;
          return "the parameter '" + k + "' is " + describe(now, k) +
                 " in the parameter file but " + describe(saved, k) +
                 " in the checkpoint '" + checkpoint_file +
                 "'; a restart must keep every parameter except Output, "
                 "Checkpointing, Load balancing, Time stepping/End time "
                 "and Maximum number of steps (or set Checkpointing/Resume "
                 "computation = false to start anew)";
        }
      return "";
    }

    template <int dim>
    std::string
    coarse_mesh_fingerprint(const dealii::Triangulation<dim> &tria)
    {
      Hash h;
      h.add(tria.n_cells(0));
      for (auto cell = tria.begin(0); cell != tria.end(0); ++cell)
        {
          for (const unsigned int v : cell->vertex_indices())
            h.add(cell->vertex(v));
          h.add(cell->material_id());
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              h.add(cell->face(f)->boundary_id());
        }
      std::ostringstream s;
      s << std::hex << std::setw(16) << std::setfill('0') << h.h;
      return s.str();
    }

    template std::string
    coarse_mesh_fingerprint<1>(const dealii::Triangulation<1> &);
    template std::string
    coarse_mesh_fingerprint<2>(const dealii::Triangulation<2> &);
    template std::string
    coarse_mesh_fingerprint<3>(const dealii::Triangulation<3> &);
  } // namespace checkpoint
} // namespace mpm
