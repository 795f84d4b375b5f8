// The interface dataset of a cycle: interface-NN.vtu (a polyline along the
// interface through the multiplier's nodes) and interface.pvd.

#include <deal.II/base/data_out_base.h>

#include <bilayer/output/output.h>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace bilayer
{
  using namespace dealii;

  void
  write_interface_vtu(const std::string                &directory,
                      const unsigned int                cycle,
                      const std::vector<InterfaceNode> &nodes,
                      const std::vector<std::string>   &trace_names,
                      SolutionRecords                  &records,
                      const unsigned int                i)
  {
    std::vector<const InterfaceNode *> along;
    for (const InterfaceNode &node : nodes)
      along.push_back(&node);
    std::sort(along.begin(),
              along.end(),
              [](const InterfaceNode *a, const InterfaceNode *b) {
                return a->s < b->s;
              });

    // Scalars, then vectors given in the node's frame (tangent, normal).
    using Scalar = std::function<double(const InterfaceNode &)>;
    using Field  = std::function<Tensor<1, 2>(const InterfaceNode &)>;
    std::vector<std::pair<std::string, Scalar>> scalars = {
      {"contact_pressure", [](const auto &n) { return n.contact_pressure; }},
      {"normal_traction", [](const auto &n) { return n.normal_traction; }},
      {"mu_c", [](const auto &n) { return n.mu_c; }},
      {"jump_normal", [](const auto &n) { return n.jump_normal; }},
      {"jump_tangential", [](const auto &n) { return n.jump_tangential; }},
      {"state", [](const auto &n) { return double(n.state); }},
      {"crack_tip", [](const auto &n) { return n.crack_tip ? 1. : 0.; }},
      {"s", [](const auto &n) { return n.s; }}};
    if (!nodes.empty() && nodes.front().frictional)
      {
        scalars.emplace_back("tangential_force",
                             [](const auto &n) { return n.tangential_force; });
        scalars.emplace_back("friction_bound",
                             [](const auto &n) { return n.friction_bound; });
        scalars.emplace_back("friction_state", [](const auto &n) {
          return double(n.friction_state);
        });
      }
    if (!nodes.empty() && nodes.front().cohesive)
      scalars.emplace_back("damage", [](const auto &n) { return n.damage; });
    std::vector<std::pair<std::string, Field>> vectors = {
      {"mu_g", [](const auto &n) { return n.mu_g; }},
      {"mu_minus", [](const auto &n) { return n.mu_minus; }},
      {"mu_plus", [](const auto &n) { return n.mu_plus; }}};
    // The traces of every subproblem (u_minus, u_plus, v_minus, ...).
    for (const unsigned int s : Layout::indices(trace_names.size()))
      vectors.emplace_back(trace_names[s],
                           [s](const auto &n) { return n.trace[s]; });

    std::vector<std::string> names;
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      ranges;
    for (const auto &scalar : scalars)
      names.push_back(scalar.first);
    const auto add_vector = [&](const std::string &name) {
      ranges.emplace_back(
        names.size(),
        names.size() + 1,
        name,
        DataComponentInterpretation::component_is_part_of_vector);
      names.push_back(name);
      names.push_back(name);
    };
    add_vector("normal");
    for (const auto &vector : vectors)
      add_vector(vector.first);

    // The values at one node, vectors turned from the frame to (x, y).
    const auto values = [&](const InterfaceNode &n) {
      std::vector<double> v;
      for (const auto &scalar : scalars)
        v.push_back(scalar.second(n));
      const Tensor<1, 2> tangent = tangent_of(n.normal);
      v.push_back(n.normal[0] + 0.);
      v.push_back(n.normal[1] + 0.);
      for (const auto &vector : vectors)
        {
          const Tensor<1, 2> c = vector.second(n);
          const Tensor<1, 2> g = c[0] * tangent + c[1] * n.normal;
          v.push_back(g[0]);
          v.push_back(g[1]);
        }
      return v;
    };

    std::vector<DataOutBase::Patch<1, 2>> patches;
    for (unsigned int i = 0; i + 1 < along.size(); ++i)
      {
        DataOutBase::Patch<1, 2> patch;
        patch.patch_index    = i;
        patch.n_subdivisions = 1;
        patch.reference_cell = ReferenceCells::Line;
        patch.data.reinit(names.size(), 2);
        for (unsigned int end = 0; end < 2; ++end)
          {
            const InterfaceNode &n = *along[i + end];
            patch.vertices[end]    = n.point;
            const auto v           = values(n);
            for (unsigned int k = 0; k < v.size(); ++k)
              patch.data(k, end) = v[k];
          }
        patches.push_back(patch);
      }

    std::ostringstream name;
    name << interface_stem(i) << "-" << std::setw(2) << std::setfill('0')
         << cycle << ".vtu";
    write_atomically(directory + "/" + name.str(), [&](std::ostream &out) {
      DataOutBase::write_vtu(
        patches, names, ranges, DataOutBase::VtkFlags(), out);
    });
    if (records.interface_pvd.size() <= i)
      records.interface_pvd.resize(i + 1);
    records.interface_pvd[i].emplace_back(records.time_of(cycle), name.str());
    if (!records.deferred)
      write_atomically(
        directory + "/" + interface_stem(i) + ".pvd", [&](std::ostream &out) {
          DataOutBase::write_pvd_record(out, records.interface_pvd[i]);
        });
  }
} // namespace bilayer
