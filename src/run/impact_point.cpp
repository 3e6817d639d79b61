// The impact point check. See impact_point.hpp.
#include "run/impact_point.hpp"

#include "model/oblique.hpp"
#include "system/structure_part.hpp"

#include <cmath>

namespace beamimpact {

bool ImpactOnBed(const BeamParams &beam, PetscReal x, PetscReal z) { return StructurePartsStrike(beam, x, z); }

PetscReal FrameHalfWidth(const BeamParams &beam, PetscReal x, const char **source)
{
  const char  *dummy;
  const char *&what = source ? *source : dummy;
  if (beam.section.source == SectionSource::Profile)
    return what = "the profile's radius there, -beam_profile", RoundSectionRadiusAt(beam.section, x);
  if (beam.section.source == SectionSource::Uniform && beam.input.width > 0)
    return what = "half -beam_width", 0.5 * beam.input.width;
  return what = "half the frame's length: its section (-beam_mass, -beam_EI or -beam_properties) gives no width",
         0.5 * beam.length;
}

ImpactPointWhere ImpactPointLocate(const BeamParams &beam, PetscReal x, PetscReal z)
{
  if (!(x >= 0 && x <= beam.length)) return ImpactPointWhere::OffBeam;
  if (ImpactOnBed(beam, x, z)) return ImpactPointWhere::Movable;
  if (z != 0 && StructurePartsHaveFace(beam)) return ImpactPointWhere::OffFace; // off the racket's face
  if (std::abs(z) > FrameHalfWidth(beam, x)) return ImpactPointWhere::OffFace;  // off the frame's section
  const std::vector<NodeHold> hold          = BeamNodeHolds(beam);
  auto                        held          = [&](PetscInt i) { return hold[i] != NodeHold::None; };
  const ImpactStencil         st            = GridImpactStencil(beam.nodes, beam.length, x);
  const bool                  on_held       = (st.w > 0 && held(st.j)) && (st.w < 1 ? held(st.j + 1) : true);
  const bool                  on_held_right = st.w == 0 && held(st.j + 1);
  return on_held || on_held_right ? ImpactPointWhere::Held : ImpactPointWhere::Movable;
}

PetscErrorCode ImpactPointCheck(MPI_Comm comm, const BeamParams &beam, PetscReal x, const char *what, PetscReal z)
{
  PetscFunctionBeginUser;
  const ImpactPointWhere where = ImpactPointLocate(beam, x, z);
  const std::string off = where == ImpactPointWhere::OffFace ? StructurePartsPointRefusal(beam, what, z, false) : "";
  PetscCheck(off.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", off.c_str()); // off a part's face (the bed's head)
  const char     *source;
  const PetscReal half = FrameHalfWidth(beam, x, &source);
  PetscCheck(where != ImpactPointWhere::OffFace, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s with -impact_z %g is not allowed: off the frame's section; a frame without a string bed is struck "
             "within its half-width across the face, |z| <= %g m (%s; a racket's head: -strings_frame beam with "
             "-head_width)",
             what, (double)z, (double)half, source);
  PetscCheck(where != ImpactPointWhere::OffBeam, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s is not allowed: the impact point must lie on the beam, 0 <= x <= L = %.12g (m)", what,
             (double)beam.length);
  const std::string held = where == ImpactPointWhere::Held ? StructurePartsPointRefusal(beam, what, z, true) : "";
  PetscCheck(held.empty(), comm, PETSC_ERR_ARG_OUTOFRANGE, "%s", held.c_str()); // a part's own (a held bed's frame)
  PetscCheck(where != ImpactPointWhere::Held, comm, PETSC_ERR_ARG_OUTOFRANGE,
             "%s is not allowed: that point is held fixed (a clamped or pinned support or inside -beam_clamp); strike "
             "a point that can move",
             what);
  PetscFunctionReturn(0);
}

PetscErrorCode ImpactAcrossCheck(MPI_Comm comm, const BeamParams &beam, PetscReal z)
{
  PetscFunctionBeginUser;
  PetscCheck(z == 0 || beam.parts.Rolls() || StructurePartsHaveFace(beam), comm, PETSC_ERR_ARG_INCOMP,
             "-impact_z %g is not allowed on a beam that cannot roll: give -beam_torsion (the frame's twist) or a "
             "string bed (-strings_frame)",
             (double)z);
  PetscFunctionReturn(0);
}

} // namespace beamimpact
