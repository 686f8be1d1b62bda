#include "reasoning/pair_graph.h"

#include <algorithm>
#include <string>

// Boost 1.74's adjacency_list trips GCC 12's -Wmaybe-uninitialized in its own code.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#pragma GCC diagnostic pop

namespace mechanist {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                    boost::no_property, std::size_t>;

struct PairGraph::Impl {
  Graph all;    ///< every pair; edge property: the pair's index
  Graph fixed;  ///< fixed pairs, plus edges from ground parts to the world vertex (last)
  std::vector<std::size_t> rank;  ///< per part: Assembly::PartRank
  std::vector<bool> ground;
};

PairGraph::PairGraph(const Assembly& assembly, const std::vector<Pair>& pairs)
    : impl_(std::make_unique<Impl>()) {
  const std::size_t n = assembly.parts().size();
  impl_->all = Graph(n);
  impl_->fixed = Graph(n + 1);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    boost::add_edge(p.a.part, p.b.part, i, impl_->all);
    if (p.type == PairType::kFixed) boost::add_edge(p.a.part, p.b.part, i, impl_->fixed);
  }
  for (std::size_t part = 0; part < n; ++part) {
    impl_->rank.push_back(assembly.PartRank(part));
    impl_->ground.push_back(assembly.part(part).ground);
    if (assembly.part(part).ground) boost::add_edge(part, n, pairs.size(), impl_->fixed);
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

std::vector<Subassembly> PairGraph::Subassemblies() const {
  const std::size_t n = part_count();
  std::vector<int> component(n + 1);
  const int count = boost::connected_components(impl_->fixed, component.data());
  std::vector<Subassembly> groups(count);
  for (std::size_t part = 0; part < n; ++part) {
    Subassembly& g = groups[component[part]];
    g.parts.push_back(part);
    g.ground = g.ground || impl_->ground[part];
  }
  std::erase_if(groups, [](const Subassembly& g) { return g.parts.empty(); });  // lone world
  const auto& rank = impl_->rank;
  for (Subassembly& g : groups) {
    std::sort(g.parts.begin(), g.parts.end(),
              [&](std::size_t x, std::size_t y) { return rank[x] < rank[y]; });
  }
  std::sort(groups.begin(), groups.end(), [&](const Subassembly& x, const Subassembly& y) {
    if (x.ground != y.ground) return x.ground;
    return rank[x.parts.front()] < rank[y.parts.front()];
  });
  return groups;
}

}  // namespace mechanist
