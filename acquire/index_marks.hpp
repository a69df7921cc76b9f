#pragma once
// Which edge an index mark (once per turn) names as a turn's position 0, by
// the edge order — not by a time window, so that an index that rises with an
// edge (an encoder's Z gated to one A/B state rises on an A edge; a toothed
// wheel's index pickup may rise with tooth 0) counts every turn alike.
//
// Each mark's place among the edges is x = (i − 1) + f: it falls between
// edges i − 1 and i, the fraction f of the way. Whether a mark that rises
// with edge k is detected a sample before or after it, x ≈ k either way. The
// index's typical place within a pitch, ψ (the circular mean of x mod 1 over
// all marks), is removed from every mark, and each mark names the edge
//   round(x − ψ) + (ψ > 1/4 ? 1 : 0),
// the edge it coincides with (up to a quarter pitch after the edge) or else
// the first edge after it. Any phase of index against teeth or lines works
// alike; a one-sample race between the index and its edge moves x by a
// sample, far less than half a pitch, and never changes the edge named. For
// an encoder the edges are A's and B's in turn, so the edge named fixes the
// A/B state the index is gated to.

#include <cstddef>
#include <vector>

namespace fourbar {

struct IndexPlacement {
  std::vector<std::size_t> reference_edges;  ///< increasing, unique: edge index of each turn's position 0
  double phase_pitch = 0;                    ///< ψ: the marks' typical place after an edge, pitches [0, 1)
};

/// `edges_s` and `marks_s` increasing. Marks outside the span of the edges
/// name none.
IndexPlacement place_index_marks(const std::vector<double>& edges_s, const std::vector<double>& marks_s);

}  // namespace fourbar
