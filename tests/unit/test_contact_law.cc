// The contact law at one node (contact/contact_law.h): approaching fields
// lose their normal relative velocity, separating ones keep theirs; Coulomb
// friction sticks below mu times the normal correction and slips by exactly
// that much above it; no separation gives the centre-of-mass velocity; a
// rigid field keeps its velocity and the others meet it; held contact (for
// the stress update's velocities) acts on separating fields too; the
// momentum of the fields at the node is kept to round-off, also with three
// fields; the gap check finds fields apart by their centroids' distance
// along the normal against the touching distance (whose formula matches a
// particle lattice), and fields apart take no part.
#define BOOST_TEST_MODULE contact_law
#ifndef BOOST_TEST_DYN_LINK
#  define BOOST_TEST_DYN_LINK
#endif
#include <mpm/contact/contact_law.h>

#include <boost/test/unit_test.hpp>

using namespace dealii;
using mpm::contact::FieldAtNode;
using Law = mpm::Parameters::Contact::Law;

namespace
{
  mpm::Parameters::Contact
  law(const Law l, const double mu = 0)
  {
    mpm::Parameters::Contact c;
    c.law      = l;
    c.friction = mu;
    return c;
  }

  /// Field 0 above field 1 (the contact normal of field 0 points down).
  std::array<FieldAtNode<2>, 2>
  two_fields(const Tensor<1, 2> &v0, const Tensor<1, 2> &v1)
  {
    std::array<FieldAtNode<2>, 2> f;
    f[0].mass             = 2.;
    f[0].velocity         = v0;
    f[0].mass_gradient[1] = -3.; // sum m grad N points out of the field
    f[1].mass             = 5.;
    f[1].velocity         = v1;
    f[1].mass_gradient[1] = 4.;
    mpm::contact::set_contact_normals(f.data(), 2);
    return f;
  }

  Tensor<1, 2>
  vec(const double x, const double y)
  {
    Tensor<1, 2> v;
    v[0] = x;
    v[1] = y;
    return v;
  }

  /// Field 0 (mass 2, velocity @p v0) on a rigid field at rest below it.
  std::array<FieldAtNode<2>, 2>
  on_rigid_plane(const Tensor<1, 2> &v0)
  {
    std::array<FieldAtNode<2>, 2> f;
    f[0].mass             = 2.;
    f[0].velocity         = v0;
    f[0].mass_gradient[1] = -1.;
    f[1].mass             = 1.;
    f[1].rigid            = true;
    f[1].mass_gradient[1] = 1.;
    mpm::contact::set_contact_normals(f.data(), 2);
    return f;
  }

  template <std::size_t n>
  Tensor<1, 2>
  momentum(const std::array<FieldAtNode<2>, n> &f)
  {
    Tensor<1, 2> p;
    for (const auto &a : f)
      p += a.mass * a.velocity;
    return p;
  }
} // namespace

BOOST_AUTO_TEST_CASE(normals_are_opposite_and_unit)
{
  const auto f = two_fields(vec(0, 0), vec(0, 0));
  BOOST_TEST(f[0].normal[1] == -1.);
  BOOST_TEST(f[1].normal[1] == 1.);
  BOOST_TEST(f[0].normal[0] == 0.);
}

BOOST_AUTO_TEST_CASE(frictionless_removes_normal_approach_only)
{
  auto               f  = two_fields(vec(1, -2), vec(-0.5, 1));
  const Tensor<1, 2> p0 = momentum(f);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::frictionless), f.data(), 2));
  // normal velocities equal (the centre of mass's), tangential untouched
  const double v_cm_y = (2. * -2 + 5. * 1) / 7.;
  BOOST_TEST(std::abs(f[0].velocity[1] - v_cm_y) < 1e-15);
  BOOST_TEST(std::abs(f[1].velocity[1] - v_cm_y) < 1e-15);
  BOOST_TEST(f[0].velocity[0] == 1.);
  BOOST_TEST(f[1].velocity[0] == -0.5);
  BOOST_TEST((momentum(f) - p0).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(separating_fields_are_left_alone)
{
  for (const Law l : {Law::frictionless, Law::coulomb})
    {
      auto f = two_fields(vec(1, 2), vec(0, -1));
      BOOST_TEST(!mpm::contact::resolve_contact(law(l, 0.5), f.data(), 2));
      BOOST_TEST(f[0].velocity == vec(1, 2));
      BOOST_TEST(f[1].velocity == vec(0, -1));
    }
}

BOOST_AUTO_TEST_CASE(coulomb_sticks_below_the_friction_limit)
{
  // relative tangential speed 0.1, normal approach 1: mu = 0.5 sticks
  auto               f  = two_fields(vec(0.1, -1), vec(0, 0));
  const Tensor<1, 2> p0 = momentum(f);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::coulomb, 0.5), f.data(), 2));
  BOOST_TEST((f[0].velocity - f[1].velocity).norm() < 1e-15);
  BOOST_TEST((momentum(f) - p0).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(coulomb_slip_is_limited_by_mu)
{
  // field 0 over a rigid field at rest: approach 1, slip 2, mu = 0.3
  auto f = on_rigid_plane(vec(2, -1));
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::coulomb, 0.3), f.data(), 2));
  BOOST_TEST(std::abs(f[0].velocity[0] - (2 - 0.3 * 1)) < 1e-15);
  BOOST_TEST(std::abs(f[0].velocity[1]) < 1e-15);
  BOOST_TEST(f[1].velocity.norm() == 0.); // the rigid field keeps its own
}

BOOST_AUTO_TEST_CASE(coulomb_slip_between_two_fields_keeps_momentum)
{
  auto               f       = two_fields(vec(3, -1), vec(-1, 0.5));
  const Tensor<1, 2> p0      = momentum(f);
  const Tensor<1, 2> before0 = f[0].velocity, before1 = f[1].velocity;
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::coulomb, 0.2), f.data(), 2));
  BOOST_TEST((momentum(f) - p0).norm() < 1e-14);
  // tangential impulse = mu times normal impulse, on each field
  const Tensor<1, 2> impulse = f[0].mass * (f[0].velocity - before0);
  BOOST_TEST(std::abs(std::abs(impulse[0]) - 0.2 * std::abs(impulse[1])) <
             1e-14);
  BOOST_TEST(((f[1].mass * (f[1].velocity - before1)) + impulse).norm() <
             1e-14);
  // still sliding: the tangential velocities differ
  BOOST_TEST(std::abs(f[0].velocity[0] - f[1].velocity[0]) > 0.1);
}

BOOST_AUTO_TEST_CASE(no_separation_gives_the_centre_of_mass_velocity)
{
  auto               f  = two_fields(vec(1, 2), vec(0, -1)); // separating
  const Tensor<1, 2> p0 = momentum(f);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::no_separation), f.data(), 2));
  const Tensor<1, 2> v_cm = p0 / 7.;
  BOOST_TEST((f[0].velocity - v_cm).norm() < 1e-15);
  BOOST_TEST((f[1].velocity - v_cm).norm() < 1e-15);
}

BOOST_AUTO_TEST_CASE(three_fields_keep_momentum)
{
  std::array<FieldAtNode<2>, 3> f;
  const double                  m[3] = {1., 2., 3.};
  const Tensor<1, 2>            v[3] = {vec(1, 0), vec(-1, 0.5), vec(0, -1)};
  const Tensor<1, 2>            g[3] = {vec(1, 0), vec(-1, -0.2), vec(0, -1)};
  for (unsigned int a = 0; a < 3; ++a)
    {
      f[a].mass          = m[a];
      f[a].velocity      = v[a];
      f[a].mass_gradient = g[a];
    }
  mpm::contact::set_contact_normals(f.data(), 3);
  const Tensor<1, 2> p0 = momentum(f);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::coulomb, 0.4), f.data(), 3));
  BOOST_TEST((momentum(f) - p0).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(held_contact_acts_on_separating_fields)
{
  // what the stress update's velocities get where the motion has contact
  auto               f  = two_fields(vec(1, 2), vec(0, -1)); // separating
  const Tensor<1, 2> p0 = momentum(f);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::frictionless), f.data(), 2, true));
  BOOST_TEST(std::abs(f[0].velocity[1] - f[1].velocity[1]) < 1e-15);
  BOOST_TEST(f[0].velocity[0] == 1.); // tangential untouched
  BOOST_TEST((momentum(f) - p0).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(held_coulomb_contact_on_separating_field)
{
  // field 0 leaves a rigid plane at rest (normal relative velocity -1,
  // slip 0.5): held, its normal velocity is removed, and its slip reduced
  // by mu times that correction, 0.3
  auto f = on_rigid_plane(vec(0.5, 1));
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::coulomb, 0.3), f.data(), 2, true));
  BOOST_TEST(std::abs(f[0].velocity[0] - 0.2) < 1e-15);
  BOOST_TEST(std::abs(f[0].velocity[1]) < 1e-15);
}

BOOST_AUTO_TEST_CASE(centroid_offset_of_a_particle_lattice)
{
  // n particles per cell direction at the centres of their sub-cells,
  // filling the half-line beyond a node: their N-weighted centroid lies
  // centroid_offset((1/n)^2) cell heights from the node
  for (unsigned int n = 1; n <= 6; ++n)
    {
      double moment = 0, weight = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          const double x = (k + 0.5) / n, N = 1 - x;
          moment += N * x;
          weight += N;
        }
      BOOST_TEST(std::abs(moment / weight -
                          mpm::contact::centroid_offset(1. / (n * n))) < 1e-15);
    }
  BOOST_TEST(mpm::contact::centroid_offset(0.25) == 0.375);
}

BOOST_AUTO_TEST_CASE(gap_check_by_centroid_distance_along_the_normal)
{
  // field 0 above field 1: its normal points down, so the gap is
  // centroid_0 - centroid_1 along y; a tangential offset does not count.
  // Touching, the centroids would be 0.375 + 0.375 apart.
  auto f              = two_fields(vec(0, -1), vec(0, 0)); // approaching
  f[0].centroid       = vec(5, 0.8);
  f[1].centroid       = vec(0, 0);
  f[0].surface_offset = f[1].surface_offset = 0.375;
  BOOST_TEST(mpm::contact::mark_fields_apart(f.data(), 2, 0.) == 0u);
  BOOST_TEST(f[0].apart);
  BOOST_TEST(f[1].apart);
  BOOST_TEST(
    !mpm::contact::resolve_contact(law(Law::frictionless), f.data(), 2));
  BOOST_TEST(f[0].velocity[1] == -1.); // no contact: untouched
  BOOST_TEST(mpm::contact::mark_fields_apart(f.data(), 2, 0.06) == 2u);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::frictionless), f.data(), 2));
  BOOST_TEST(std::abs(f[0].velocity[1] - f[1].velocity[1]) < 1e-15);
}

BOOST_AUTO_TEST_CASE(gap_check_against_a_rigid_field)
{
  // a rigid plane below field 0, whose centroid lies 0.6 above the
  // plane's; touching they would be 0.7 apart: in contact, unless the
  // tolerance lets them overlap by more than 0.1
  auto f              = on_rigid_plane(vec(0, -1));
  f[0].centroid       = vec(0, 0.6);
  f[0].surface_offset = 0.3;
  f[1].surface_offset = 0.4;
  BOOST_TEST(mpm::contact::mark_fields_apart(f.data(), 2, -0.2) == 0u);
  BOOST_TEST(mpm::contact::mark_fields_apart(f.data(), 2, 0.) == 2u);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::frictionless), f.data(), 2));
  BOOST_TEST(std::abs(f[0].velocity[1]) < 1e-15);
}

BOOST_AUTO_TEST_CASE(gap_check_leaves_the_touching_pair_of_three)
{
  // fields 0 and 1 touch, field 2 is far from both: 0 and 1 exchange
  // momentum between them only, field 2 keeps its velocity
  std::array<FieldAtNode<2>, 3> f;
  const double                  m[3] = {1., 2., 3.};
  const Tensor<1, 2>            v[3] = {vec(1, 0), vec(-1, 0), vec(0, 1)};
  const Tensor<1, 2>            g[3] = {vec(1, 0), vec(-1, 0), vec(0, -1)};
  const Tensor<1, 2>            x[3] = {vec(0, 0), vec(0.5, 0), vec(0, 1.5)};
  for (unsigned int a = 0; a < 3; ++a)
    {
      f[a].mass           = m[a];
      f[a].velocity       = v[a];
      f[a].mass_gradient  = g[a];
      f[a].centroid       = x[a];
      f[a].surface_offset = 0.35;
    }
  mpm::contact::set_contact_normals(f.data(), 3);
  BOOST_TEST(mpm::contact::mark_fields_apart(f.data(), 3, 0.) == 2u);
  BOOST_TEST(f[2].apart);
  const Tensor<1, 2> p01 = m[0] * v[0] + m[1] * v[1];
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::frictionless), f.data(), 3));
  BOOST_TEST((f[2].velocity - v[2]).norm() == 0.);
  BOOST_TEST((m[0] * f[0].velocity + m[1] * f[1].velocity - p01).norm() <
             1e-14);
  BOOST_TEST(std::abs(f[0].velocity[0] - f[1].velocity[0]) < 1e-15);
}
