#include <mpm/materials/rigid.h>

using mpm::materials::Rigid;
MPM_REGISTER_MATERIAL(Rigid,
                      "rigid",
                      "A body that moves as its Prescribed velocity says: no "
                      "stress, no stiffness; the nodes it reaches follow it "
                      "(quasi-static integrator).")
