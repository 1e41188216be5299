// The recursion of Algorithm 1, shared by the solid and the surface decomposition. Breadth first:
// every round processes all pending pieces in parallel, each into its own slot, then takes the
// outcomes in piece order, so the result does not depend on the number of threads. The caller
// runs it in its arena (acd/algo/parallel.hpp).
#pragma once

#include <tbb/parallel_for.h>

#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace acd {

/// The pieces that came out final, each with the outcome that made it final.
template <class Piece, class Outcome>
struct FinalPieces {
  std::vector<Piece> pieces;
  std::vector<Outcome> outcomes;
};

/// Runs the rounds until no piece is pending. `process(piece)` gives an Outcome with a `final`
/// flag and its `children`; `account(outcome)` adds its statistics. A piece that is not final is
/// replaced by its children (`split(piece, outcome, next)` adds them to the next round), unless
/// the pieces would then outnumber `maxPieces`: it is final after all, and `capped(outcome)` says why.
template <class Piece, class Process, class Account, class Capped, class Split>
auto runRounds(std::vector<Piece> pending, int maxPieces, const Process& process, const Account& account,
               const Capped& capped, const Split& split, const std::function<void(int, int)>& progress) {
  using Outcome = std::invoke_result_t<const Process&, const Piece&>;
  FinalPieces<Piece, Outcome> finals;
  while (!pending.empty()) {
    std::vector<Outcome> outcomes(pending.size());
    tbb::parallel_for(std::size_t(0), pending.size(), [&](std::size_t i) { outcomes[i] = process(pending[i]); });
    std::vector<Piece> next;
    for (std::size_t i = 0; i < pending.size(); ++i) {
      Outcome& out = outcomes[i];
      account(out);
      const int total = static_cast<int>(finals.pieces.size() + next.size() + out.children.size() + pending.size() - i);
      if (out.final || total > maxPieces) {
        if (!out.final) capped(out);
        finals.pieces.push_back(std::move(pending[i]));
        finals.outcomes.push_back(std::move(out));
      } else {
        split(pending[i], out, next);
      }
    }
    pending = std::move(next);
    if (progress) progress(static_cast<int>(finals.pieces.size()), static_cast<int>(pending.size()));
  }
  return finals;
}

}  // namespace acd
