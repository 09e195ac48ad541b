#include <deal.II/base/utilities.h>

#include <mpm/parameters/parsing.h>
#include <mpm/utilities/input_error.h>

namespace mpm
{
  namespace Parameters
  {
    using namespace dealii;

    std::vector<unsigned int>
    parse_unsigned_list(const std::string &text,
                        const unsigned int n,
                        const std::string &entry)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      if (parts.size() != n && parts.size() != 1)
        throw InputError("Parameter '" + entry + "' = '" + text +
                         "': expected 1 or " + std::to_string(n) +
                         " comma-separated integers");
      std::vector<unsigned int> out;
      for (const auto &p : parts)
        {
          const int v = Utilities::string_to_int(p);
          if (v <= 0)
            throw InputError("Parameter '" + entry + "' = '" + text +
                             "': entries must be positive integers");
          out.push_back(v);
        }
      if (out.size() == 1)
        out.resize(n, out[0]);
      return out;
    }

    std::string
    default_expression(const int dim)
    {
      std::string s = "0";
      for (int d = 1; d < dim; ++d)
        s += "; 0";
      return s;
    }

    std::string
    default_point(const int dim, const double value)
    {
      std::string s;
      for (int d = 0; d < dim; ++d)
        s += (d ? ", " : "") + Utilities::to_string(value);
      return s;
    }

    std::vector<types::boundary_id>
    parse_id_list(const std::string &text)
    {
      std::vector<types::boundary_id> ids;
      for (const int i :
           Utilities::string_to_int(Utilities::split_string_list(text, ',')))
        ids.push_back(static_cast<types::boundary_id>(i));
      return ids;
    }

    template <int dim>
    Point<dim>
    parse_point(const std::string &text, const std::string &entry)
    {
      const auto parts = Utilities::split_string_list(text, ',');
      if (parts.size() != dim)
        throw InputError("Parameter '" + entry + "' = '" + text +
                         "': expected " + std::to_string(dim) +
                         " comma-separated coordinates");
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = Utilities::string_to_double(parts[d]);
      return p;
    }

    template Point<1>
    parse_point<1>(const std::string &, const std::string &);
    template Point<2>
    parse_point<2>(const std::string &, const std::string &);
    template Point<3>
    parse_point<3>(const std::string &, const std::string &);
  } // namespace Parameters
} // namespace mpm
