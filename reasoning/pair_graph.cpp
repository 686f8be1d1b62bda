#include "reasoning/pair_graph.h"

#include <algorithm>
#include <deque>
#include <utility>

// Boost 1.74's graph headers trip GCC 12's -Wmaybe-uninitialized in their own code.
#pragma GCC diagnostic push
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/pending/disjoint_sets.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>
#pragma GCC diagnostic pop

namespace mechanist {

// Compressed sparse rows: one array of edges for the whole graph, not a container per vertex
// (an assembly of 100,000 parts would otherwise cost hundreds of thousands of allocations).
// Each pair is an edge in both directions; the edge property is the pair's index.
using Graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, std::size_t>;

struct PairGraph::Impl {
  Graph all;
  std::vector<Subassembly> subassemblies;
  std::vector<std::size_t> subassembly_of;  ///< per part
};

namespace {

/// The subassemblies from each part's representative among the parts joined by fixed pairs
/// (`group_of`, ground parts joined to the world), visiting the parts in id order (`by_id`):
/// each group's parts come in order and the groups in the order of their first parts, with no
/// sort (the ground group of a large assembly holds most of its parts).
std::vector<Subassembly> GroupParts(const std::vector<std::size_t>& group_of,
                                    const std::vector<std::size_t>& by_id,
                                    const std::vector<bool>& ground) {
  std::vector<long> group_index(group_of.size() + 1, -1);  // per representative
  std::vector<Subassembly> groups;
  for (std::size_t part : by_id) {
    long& g = group_index[group_of[part]];
    if (g < 0) {
      g = static_cast<long>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<std::size_t>(g)].parts.push_back(part);
    groups[static_cast<std::size_t>(g)].ground |= ground[part];
  }
  // All ground parts are one group: it goes first, the others keep their order.
  const auto first_ground =
      std::find_if(groups.begin(), groups.end(), [](const Subassembly& g) { return g.ground; });
  if (first_ground != groups.end()) std::rotate(groups.begin(), first_ground, first_ground + 1);
  return groups;
}

}  // namespace

PairGraph::PairGraph(const Assembly& assembly, const std::vector<Pair>& pairs)
    : impl_(std::make_unique<Impl>()) {
  const std::size_t n = assembly.parts().size();
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<std::size_t> index;
  edges.reserve(2 * pairs.size());
  index.reserve(2 * pairs.size());
  std::vector<std::size_t> set_rank(n + 1), parent(n + 1);
  using Map = boost::iterator_property_map<std::vector<std::size_t>::iterator,
                                           boost::identity_property_map>;
  boost::disjoint_sets<Map, Map> sets(Map(set_rank.begin()), Map(parent.begin()));
  for (std::size_t v = 0; v <= n; ++v) sets.make_set(v);
  // One read of the pairs for the edges and the fixed unions.
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    edges.emplace_back(p.a.part, p.b.part);
    edges.emplace_back(p.b.part, p.a.part);
    index.insert(index.end(), {i, i});
    if (p.type == PairType::kFixed) sets.union_set(p.a.part, p.b.part);
  }
  impl_->all =
      Graph(boost::edges_are_unsorted_multi_pass, edges.begin(), edges.end(), index.begin(), n);

  std::vector<std::size_t> by_id(n);  // the parts ordered by id (inverse of Assembly::PartRank)
  std::vector<bool> ground;
  ground.reserve(n);
  for (std::size_t part = 0; part < n; ++part) {
    by_id.at(assembly.PartRank(part)) = part;
    ground.push_back(assembly.IsGround(part));
    if (assembly.IsGround(part)) sets.union_set(part, n);
  }
  std::vector<std::size_t> group_of(n);
  for (std::size_t part = 0; part < n; ++part) group_of[part] = sets.find_set(part);
  impl_->subassemblies = GroupParts(group_of, by_id, ground);
  impl_->subassembly_of.resize(n);
  for (std::size_t g = 0; g < impl_->subassemblies.size(); ++g) {
    for (const std::size_t part : impl_->subassemblies[g].parts) impl_->subassembly_of[part] = g;
  }
}

PairGraph::~PairGraph() = default;
PairGraph::PairGraph(PairGraph&&) noexcept = default;
PairGraph& PairGraph::operator=(PairGraph&&) noexcept = default;

std::size_t PairGraph::part_count() const { return boost::num_vertices(impl_->all); }

std::vector<std::size_t> PairGraph::PairsOf(std::size_t part) const {
  std::vector<std::size_t> result;
  for (const auto& edge : boost::make_iterator_range(boost::out_edges(part, impl_->all))) {
    result.push_back(impl_->all[edge]);
  }
  std::sort(result.begin(), result.end());
  return result;
}

std::vector<std::size_t> PairGraph::Reachable(
    std::span<const std::size_t> from,
    const std::function<bool(std::size_t pair, std::size_t at, std::size_t to)>& cross) const {
  std::vector<bool> seen(part_count(), false);
  std::deque<std::size_t> queue;
  for (const std::size_t part : from) {
    if (!seen[part]) seen[part] = true, queue.push_back(part);
  }
  std::vector<std::size_t> reached;
  while (!queue.empty()) {
    const std::size_t at = queue.front();
    queue.pop_front();
    reached.push_back(at);
    for (const auto& edge : boost::make_iterator_range(boost::out_edges(at, impl_->all))) {
      const std::size_t to = boost::target(edge, impl_->all);
      if (seen[to] || !cross(impl_->all[edge], at, to)) continue;
      seen[to] = true;
      queue.push_back(to);
    }
  }
  std::sort(reached.begin(), reached.end());
  return reached;
}

const std::vector<Subassembly>& PairGraph::Subassemblies() const { return impl_->subassemblies; }

const std::vector<std::size_t>& PairGraph::SubassemblyOf() const { return impl_->subassembly_of; }

}  // namespace mechanist
