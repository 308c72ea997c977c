// ReducedTets: the reducer's output as the tet caster's mesh. It lives in the tool, which links
// both modules, so that neither module has to depend on the other.
#ifndef adaptivert_ReducedTets_h
#define adaptivert_ReducedTets_h

#if defined(ART_HAVE_Reduction) && defined(ART_HAVE_TetRayCast)
#include "TetMesh.h"
#include "TetReducer.h"

namespace cli
{
art::TetMesh ToTetMesh(const art::ReducedMesh& r);
}
#endif

#endif
