#include <deal.II/base/utilities.h>

#include <mpm/utilities/expression.h>
#include <mpm/utilities/input_error.h>

#include <cctype>
#include <set>

#include <muParser.h>

namespace mpm
{
  namespace
  {
    /// Identifiers used in an expression (names of variables, constants
    /// and functions alike).
    std::set<std::string>
    identifiers(const std::string &text)
    {
      std::set<std::string> ids;
      for (std::size_t i = 0; i < text.size();)
        if (std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_')
          {
            std::size_t j = i;
            while (j < text.size() &&
                   (std::isalnum(static_cast<unsigned char>(text[j])) ||
                    text[j] == '_'))
              ++j;
            ids.insert(text.substr(i, j - i));
            i = j;
          }
        else if (std::isdigit(static_cast<unsigned char>(text[i])) ||
                 text[i] == '.')
          {
            // skip a number including an exponent like 1e-3
            std::size_t j = i;
            while (j < text.size() &&
                   (std::isdigit(static_cast<unsigned char>(text[j])) ||
                    text[j] == '.'))
              ++j;
            if (j < text.size() && (text[j] == 'e' || text[j] == 'E'))
              {
                ++j;
                if (j < text.size() && (text[j] == '+' || text[j] == '-'))
                  ++j;
                while (j < text.size() &&
                       std::isdigit(static_cast<unsigned char>(text[j])))
                  ++j;
              }
            i = j;
          }
        else
          ++i;
      return ids;
    }
  } // namespace

  /// One muparser per component, bound to a shared variable array.
  template <int n_vars>
  struct Expression<n_vars>::Parsers
  {
    std::vector<mu::Parser>        components;
    std::array<double, n_vars + 1> variables{}; // coordinates, then t
  };

  template <int n_vars>
  Expression<n_vars>::Expression(const std::string &text,
                                 const unsigned int n_components,
                                 const std::string &variables,
                                 const std::map<std::string, double> &constants,
                                 const bool         time_dependent,
                                 const std::string &where)
  {
    std::vector<std::string> parts =
      dealii::Utilities::split_string_list(text, ';');
    if (parts.size() != n_components)
      throw InputError(where + " = '" + text + "': expected " +
                       std::to_string(n_components) +
                       " expression(s) separated by ';', found " +
                       std::to_string(parts.size()));

    std::set<std::string> vars;
    for (const auto &v : dealii::Utilities::split_string_list(variables, ','))
      vars.insert(v);
    if (time_dependent)
      vars.insert("t");
    constant = true;
    for (const auto &id : identifiers(text))
      if (vars.count(id))
        constant = false;

    std::string all_vars = variables + (time_dependent ? ",t" : "");
    const auto  names    = dealii::Utilities::split_string_list(variables, ',');
    parsers              = std::make_shared<Parsers>();
    parsers->components.resize(n_components);
    constant_value.resize(n_components);
    try
      {
        for (unsigned int c = 0; c < n_components; ++c)
          {
            mu::Parser &p = parsers->components[c];
            for (unsigned int v = 0; v < names.size() && v < n_vars; ++v)
              p.DefineVar(names[v], &parsers->variables[v]);
            if (time_dependent)
              p.DefineVar("t", &parsers->variables[n_vars]);
            p.DefineConst("pi", M_PI);
            p.DefineConst("Pi", M_PI);
            for (const auto &[name, value] : constants)
              p.DefineConst(name, value);
            p.SetExpr(parts[c]);
            constant_value[c] = p.Eval(); // reports syntax errors now
          }
      }
    catch (const mu::Parser::exception_type &e)
      {
        throw InputError(where + " = '" + text +
                         "': cannot parse the expression (variables: " +
                         all_vars + "): " + e.GetMsg());
      }
  }

  template <int n_vars>
  void
  Expression<n_vars>::value(const dealii::Point<n_vars> &p,
                            const double                 t,
                            double                      *out) const
  {
    if (constant)
      {
        std::copy(constant_value.begin(), constant_value.end(), out);
        return;
      }
    for (unsigned int d = 0; d < n_vars; ++d)
      parsers->variables[d] = p[d];
    parsers->variables[n_vars] = t;
    for (unsigned int c = 0; c < parsers->components.size(); ++c)
      out[c] = parsers->components[c].Eval();
  }

  std::map<std::string, double>
  parse_constants(const std::string &text, const std::string &entry)
  {
    std::map<std::string, double> out;
    for (const auto &item : dealii::Utilities::split_string_list(text, ','))
      {
        const auto kv = dealii::Utilities::split_string_list(item, '=');
        if (kv.size() != 2 || kv[0].empty())
          throw InputError(entry + ": '" + item +
                           "' is not of the form name=value");
        // the expressions' variables: a constant of that name would
        // silently replace the coordinate or the time everywhere
        if (kv[0] == "x" || kv[0] == "y" || kv[0] == "z" || kv[0] == "t")
          throw InputError(entry + ": '" + kv[0] +
                           "' is a variable of the expressions (the "
                           "coordinates x, y, z and the time t); a constant "
                           "of that name would replace it in every "
                           "expression. Choose another name");
        try
          {
            out[kv[0]] = dealii::Utilities::string_to_double(kv[1]);
          }
        catch (...)
          {
            throw InputError(entry + ": the value of '" + kv[0] +
                             "' is not a number");
          }
      }
    return out;
  }

  template class Expression<1>;
  template class Expression<2>;
  template class Expression<3>;
  template class Expression<4>;
  template class Expression<6>;
} // namespace mpm
