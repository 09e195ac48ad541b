// The contact law at one node (contact/contact_law.h): approaching fields
// lose their normal relative velocity, separating ones keep theirs; Coulomb
// friction sticks below mu times the normal correction and slips by exactly
// that much above it; no separation gives the centre-of-mass velocity; a
// rigid field keeps its velocity and the others meet it; held contact (for
// the stress update's velocities) acts on separating fields too; the
// momentum of the fields at the node is kept to round-off, also with three
// fields.
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
  std::array<FieldAtNode<2>, 2> f;
  f[0].mass             = 2.;
  f[0].velocity         = vec(2, -1);
  f[0].mass_gradient[1] = -1.;
  f[1].mass             = 1.;
  f[1].rigid            = true;
  f[1].mass_gradient[1] = 1.;
  mpm::contact::set_contact_normals(f.data(), 2);
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
  std::array<FieldAtNode<2>, 2> f;
  f[0].mass             = 2.;
  f[0].velocity         = vec(0.5, 1);
  f[0].mass_gradient[1] = -1.;
  f[1].mass             = 1.;
  f[1].rigid            = true;
  f[1].mass_gradient[1] = 1.;
  mpm::contact::set_contact_normals(f.data(), 2);
  BOOST_TEST(
    mpm::contact::resolve_contact(law(Law::coulomb, 0.3), f.data(), 2, true));
  BOOST_TEST(std::abs(f[0].velocity[0] - 0.2) < 1e-15);
  BOOST_TEST(std::abs(f[0].velocity[1]) < 1e-15);
}
