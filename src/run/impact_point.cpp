// The impact point check. See impact_point.hpp.
#include "run/impact_point.hpp"

namespace beamimpact {

ImpactPointWhere ImpactPointLocate(const BeamParams &beam, PetscReal x)
{
  if (!(x >= 0 && x <= beam.length)) return ImpactPointWhere::OffBeam;
  const std::vector<NodeHold> hold = BeamNodeHolds(beam);
  auto                        held = [&](PetscInt i) { return hold[i] != NodeHold::None; };
  const ImpactStencil         st            = GridImpactStencil(beam.nodes, beam.length, x);
  const bool                  on_held       = (st.w > 0 && held(st.j)) && (st.w < 1 ? held(st.j + 1) : true);
  const bool                  on_held_right = st.w == 0 && held(st.j + 1);
  return on_held || on_held_right ? ImpactPointWhere::Held : ImpactPointWhere::Movable;
}

PetscErrorCode ImpactPointCheck(MPI_Comm comm, const BeamParams &beam, PetscReal x, const char *what)
{
  PetscFunctionBeginUser;
  const ImpactPointWhere where = ImpactPointLocate(beam, x);
  PetscCheck(where != ImpactPointWhere::OffBeam, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s is not allowed: the impact point must lie on the beam, 0 <= x <= L = %.12g (m)", what, (double)beam.length);
  PetscCheck(where != ImpactPointWhere::Held, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s is not allowed: that point is held fixed (a clamped or pinned support or inside -beam_clamp); strike a point that can move", what);
  PetscFunctionReturn(0);
}

} // namespace beamimpact
