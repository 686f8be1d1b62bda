#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "reasoning/pair.h"

namespace mechanist {

/// Parts joined by fixed pairs (directly or through other parts), moving as one body.
/// `parts` are part indices ordered by part id; `ground` when one of them is fixed to the
/// world (all ground parts are one subassembly).
struct Subassembly {
  std::vector<std::size_t> parts;
  bool ground = false;
};

/// The pair graph: parts are vertices, pairs are edges (Boost.Graph behind this facade).
class PairGraph {
 public:
  /// Builds the graph of `pairs` over the parts of `assembly`; keeps references to neither.
  PairGraph(const Assembly& assembly, const std::vector<Pair>& pairs);
  ~PairGraph();
  PairGraph(PairGraph&&) noexcept;
  PairGraph& operator=(PairGraph&&) noexcept;

  std::size_t part_count() const;
  /// Indices (into the pairs given at construction) of the pairs that touch `part`, ascending.
  std::vector<std::size_t> PairsOf(std::size_t part) const;
  /// The parts reached breadth-first from the parts `from` over the pairs, crossing pair
  /// `pair` (an index into the pairs given at construction) from part `at` to part `to` when
  /// `cross(pair, at, to)` says so; `from` included, ascending.
  std::vector<std::size_t> Reachable(
      std::span<const std::size_t> from,
      const std::function<bool(std::size_t pair, std::size_t at, std::size_t to)>& cross) const;
  /// The subassemblies: connected components over fixed pairs, with every ground part joined
  /// to the world. Ordered by their first part's id; the ground one first when it exists.
  const std::vector<Subassembly>& Subassemblies() const;
  /// Per part: the index of its subassembly in Subassemblies().
  const std::vector<std::size_t>& SubassemblyOf() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mechanist
