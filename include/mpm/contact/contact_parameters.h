#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace mpm
{
  namespace Parameters
  {
    /**
     * subsection Contact: how bodies of different velocity fields meet
     * (contact/multi_field_contact.h). Each body's field is its own
     * `Contact field` entry. Part of the parameter file of
     * parameters/parameters.h, kept beside the contact code that reads it.
     */
    struct Contact
    {
      enum class Law
      {
        none,          ///< one velocity field for every body
        no_separation, ///< fields meet and stick, and never separate
        frictionless,  ///< no penetration; free sliding and separation
        coulomb        ///< no penetration; stick or slip with mu
      };
      Law    law      = Law::none;
      double friction = 0;
      /// contact only where the fields touch (the gap check), within
      /// gap_tolerance cell heights
      static constexpr double default_gap_tolerance = 0.02;
      bool                    gap_check             = false;
      double                  gap_tolerance         = default_gap_tolerance;

      bool
      enabled() const
      {
        return law != Law::none;
      }

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /// The name of @p law as the parameter file spells it.
    std::string
    law_name(const Contact::Law law);
  } // namespace Parameters
} // namespace mpm
