#include <mpm/materials/rigid.h>

using mpm::materials::Rigid;
MPM_REGISTER_MATERIAL(Rigid,
                      "rigid",
                      "a body that moves as its Prescribed velocity says, "
                      "with no stress and no stiffness; the nodes it "
                      "reaches follow it. Only its Density is used (the "
                      "mass that marks the nodes it reaches). Needs a "
                      "Prescribed velocity and the quasi-static "
                      "integrator.")
