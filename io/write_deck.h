// Solver decks written by quadmesh rather than by Gmsh (whose writers make every
// boundary line a truss element and give no node sets): Abaqus / CalculiX .inp,
// Nastran .bdf, I-DEAS universal .unv. README "Solver decks" and docs/outputs.md
// say what each holds.
#pragma once

#include "io/deck_mesh.h"

#include <ostream>
#include <string>

namespace qm::io {

/// .inp: *NODE, *ELEMENT (ELSET = the surface group), per group an *NSET and an
/// element-edge *SURFACE, TYPE=ELEMENT (sides S1-S4 of plane elements; S3-S6 of
/// shells, CalculiX's numbering of shell edges). The part only: the user adds a
/// material, a section on the element set and a step.
void write_inp(std::ostream& out, const DeckMesh& deck);

/// .bdf: bulk data entries to INCLUDE after BEGIN BULK: GRID* (large field), the
/// elements (CQUAD4 / CQUAD8 with PID 1), one SET1 per group (SID from 1, its
/// name in the comment before it).
void write_bdf(std::ostream& out, const DeckMesh& deck);

/// .unv: datasets 2411 (nodes), 2412 (elements; parabolic quads listed corner,
/// edge node, corner, ... as I-DEAS orders them) and 2467 (a group of nodes per
/// group, and a group of the elements).
void write_unv(std::ostream& out, const DeckMesh& deck);

/// Writes `mesh` to `path` as the deck `format` names. Throws qm::Error(bad_input)
/// as deck_mesh does or when the file cannot be written.
void write_deck(const std::string& path, Format format, const OutputMesh& mesh, const std::string& element_type);

}  // namespace qm::io
