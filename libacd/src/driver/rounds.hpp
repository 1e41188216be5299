// The recursion of Algorithm 1, shared by the solid and the surface decomposition, with the result
// of a breadth-first run: round by round, each round's pieces in order, so the result does not
// depend on the number of threads. The pieces are not processed in rounds, though: a piece's
// children start as soon as it is cut, so that no core waits for the slowest piece of a round.
// The outcome of a piece depends on that piece only; the rounds are replayed from the finished
// tree. The caller runs it in its arena (acd/algo/parallel.hpp).
#pragma once

#include <tbb/concurrent_vector.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <atomic>
#include <functional>
#include <mutex>
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

/// Runs the recursion until no piece is pending. `process(piece)` gives an Outcome with a `final`
/// flag; `children(piece, outcome)` takes the pieces a cut made out of the outcome; `account(outcome)`
/// adds its statistics. A piece that is not final is replaced by its children (`split(piece, outcome)`
/// counts the split), unless the pieces would then outnumber `maxPieces`: it is final after all,
/// and `capped(outcome)` says why. `progress(final, pending)` is called as pieces finish.
template <class Piece, class Process, class Children, class Account, class Capped, class Split>
auto runRounds(std::vector<Piece> roots, int maxPieces, const Process& process, const Children& children,
               const Account& account, const Capped& capped, const Split& split,
               const std::function<void(int, int)>& progress) {
  using Outcome = std::invoke_result_t<const Process&, const Piece&>;
  struct Node {
    Piece piece;
    Outcome outcome;
    std::vector<std::size_t> kids;  // in the order of the cut's children
  };
  // Every piece the recursion makes, processed as soon as its parent is cut. While the tree has at
  // most maxPieces pieces, no replayed round can reach the cap (the pieces counted there head
  // disjoint subtrees, each with a leaf); past it, the tree is dropped and the rounds run as such.
  tbb::concurrent_vector<Node> tree;
  const std::size_t rootCount = roots.size();
  std::atomic<long> made{static_cast<long>(roots.size())}, finished{0}, finals{0};
  std::atomic<bool> tooMany{static_cast<long>(roots.size()) > maxPieces};
  std::mutex reporting;
  tbb::task_group tasks;
  std::function<void(std::size_t)> run = [&](std::size_t n) {
    if (tooMany) return;
    Node& node = tree[n];
    node.outcome = process(node.piece);
    if (!node.outcome.final) {
      std::vector<Piece> kids = children(node.piece, node.outcome);
      if (n >= rootCount) node.piece = Piece{};  // not needed again (a root is, should the tree be dropped)
      if ((made += static_cast<long>(kids.size())) > maxPieces) tooMany = true;
      for (Piece& kid : kids) {
        const std::size_t k = tree.push_back(Node{std::move(kid), Outcome{}, {}}) - tree.begin();
        node.kids.push_back(k);
        tasks.run([&run, k] { run(k); });
      }
    } else {
      ++finals;
    }
    ++finished;
    if (progress) {
      std::lock_guard<std::mutex> lock(reporting);
      progress(static_cast<int>(finals), static_cast<int>(made - finished));
    }
  };
  for (Piece& root : roots) {
    const std::size_t k = tree.push_back(Node{std::move(root), Outcome{}, {}}) - tree.begin();
    tasks.run([&run, k] { run(k); });
  }
  tasks.wait();

  FinalPieces<Piece, Outcome> out;
  if (!tooMany) {
    // Replay: round by round, in order.
    std::vector<std::size_t> level;
    for (std::size_t k = 0; k < rootCount; ++k) level.push_back(k);
    while (!level.empty()) {
      std::vector<std::size_t> next;
      for (std::size_t n : level) {
        Node& node = tree[n];
        account(node.outcome);
        if (node.outcome.final) {
          out.pieces.push_back(std::move(node.piece));
          out.outcomes.push_back(std::move(node.outcome));
        } else {
          split(node.piece, node.outcome);
          next.insert(next.end(), node.kids.begin(), node.kids.end());
        }
      }
      level = std::move(next);
    }
    return out;
  }
  std::vector<Piece> pending;
  for (std::size_t k = 0; k < rootCount; ++k) pending.push_back(std::move(tree[k].piece));
  tree.clear();
  while (!pending.empty()) {
    std::vector<Outcome> outcomes(pending.size());
    tbb::parallel_for(std::size_t(0), pending.size(), [&](std::size_t i) { outcomes[i] = process(pending[i]); });
    std::vector<Piece> next;
    for (std::size_t i = 0; i < pending.size(); ++i) {
      Outcome& o = outcomes[i];
      account(o);
      std::vector<Piece> kids = o.final ? std::vector<Piece>{} : children(pending[i], o);
      const int total = static_cast<int>(out.pieces.size() + next.size() + kids.size() + pending.size() - i);
      if (o.final || total > maxPieces) {
        if (!o.final) capped(o);
        out.pieces.push_back(std::move(pending[i]));
        out.outcomes.push_back(std::move(o));
      } else {
        split(pending[i], o);
        for (Piece& kid : kids) next.push_back(std::move(kid));
      }
    }
    pending = std::move(next);
    if (progress) progress(static_cast<int>(out.pieces.size()), static_cast<int>(pending.size()));
  }
  return out;
}

}  // namespace acd
