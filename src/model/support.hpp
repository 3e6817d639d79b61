// The supports of a beam end (-beam_left, -beam_right): a registry of entries, each a name, a
// help line and what it holds at its end node, the deflection y and the rotation (the slope y'
// of an Euler-Bernoulli beam, the section's psi of a Timoshenko beam). Everything else follows
// from what is held:
//   * the end condition of each theory: Euler-Bernoulli (model/euler_bernoulli.cpp) holds the
//     deflection as a held dof and the rotation by the mirror ghost y_-1 = y_1 (a half-weight
//     curvature term 2 (y_1 - y_0)/h^2 at the end node; none: the natural y'' = 0); Timoshenko
//     (model/timoshenko.cpp) holds the w and psi dofs, the rest are natural conditions;
//   * the rigid modes a uniform beam keeps (SupportRigidModes: the motions a + b x that satisfy
//     every hold; the modes check of -task modes counts them from the held dofs alike);
//   * the fundamental's scale for default windows (BeamFundamentalFrequencyEstimate).
// free, clamped and pinned are the entries of kSupports in model/support.cpp: a new support
// (a guided end, which holds only the rotation) is one more entry there. -help lists the names.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace beamimpact {

// What a node is held at, as bits: the deflection (1), the rotation (2).
enum class NodeHold : signed char {
  None  = 0,
  Pin   = 1,
  Guide = 2,
  Clamp = 3
};
inline bool     HoldsDeflection(NodeHold h) { return (static_cast<int>(h) & 1) != 0; }
inline bool     HoldsRotation(NodeHold h) { return (static_cast<int>(h) & 2) != 0; }
inline NodeHold operator|(NodeHold a, NodeHold b)
{
  return static_cast<NodeHold>(static_cast<int>(a) | static_cast<int>(b));
}

// One support: a registered entry (static storage; model/support.cpp).
struct SupportSpec {
  const char *name;  // as -beam_left and -beam_right take it
  const char *help;  // its boundary conditions in words, for -help and messages
  NodeHold    holds; // what it holds at its end node
};

// A beam end's support: a handle on a registered entry (compared by entry).
class Support {
public:
  constexpr explicit Support(const SupportSpec *s) : spec_(s) { }
  const SupportSpec   &Spec() const { return *spec_; }
  const char          *Name() const { return spec_->name; }
  NodeHold             Holds() const { return spec_->holds; }
  bool                 operator==(const Support &o) const { return spec_ == o.spec_; }
  bool                 operator!=(const Support &o) const { return spec_ != o.spec_; }
  static const Support Free, Clamped, Pinned; // the built-in entries

private:
  const SupportSpec *spec_;
};

const char *SupportName(Support s);

// The registered supports, in -help's order (the built-in ones first); SupportFind: by name
// (case-insensitive), false if none.
std::vector<Support>     Supports();
std::vector<std::string> SupportNames();
bool                     SupportFind(const std::string &name, Support *s);
// Adds an entry (static storage; a second entry of the same name is ignored). The program's
// supports are the table kSupports; this is for a module or a test that brings its own.
void SupportRegister(const SupportSpec *spec);

// Rigid modes (rad/s = 0) of a uniform beam with these end supports and nothing else held: 2
// minus the rank of the holds on the rigid motions a + b x (free-free 2: translation and
// rotation; pinned-free 1; clamped-free, pinned-pinned 0; a guided end keeps the translation).
PetscInt SupportRigidModes(Support left, Support right);

} // namespace beamimpact
