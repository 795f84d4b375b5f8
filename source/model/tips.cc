// The crack tips of a model: found on every interface, the supports of
// their velocity fields checked against the meshes, and the faces between
// plies that bound them.

#include <bilayer/model/model.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  void
  Model::update_tips(const CycleRecord &record)
  {
    // The tips (and a refusal of Fracture/Support radius) before anything
    // is computed or written.
    if (!tips_current && scene.fracture.energy_release_rate)
      {
        // The tips of each interface in turn.
        const std::vector<InterfaceCurve> &curves = domain.interface_curves();
        const std::vector<Segment>         material_faces = ply_boundaries();
        crack_tips_found.clear();
        for (const unsigned int i : Layout::indices(curves.size()))
          {
            const std::vector<CrackTip> on_i =
              tips_on(curves[i], i, material_faces);
            crack_tips_found.insert(crack_tips_found.end(),
                                    on_i.begin(),
                                    on_i.end());
          }
        tips_current = true;
      }
    if (!crack_tips_found.empty())
      check_supports(record);
  }


  std::vector<CrackTip>
  Model::tips_on(const InterfaceCurve       &curve,
                 const unsigned int          i,
                 const std::vector<Segment> &material_faces) const
  {
    // The other interfaces are obstacles of the supports.
    const std::vector<InterfaceCurve> &curves = domain.interface_curves();
    std::vector<InterfaceCurve>        others;
    for (const unsigned int j : Layout::indices(curves.size()))
      if (j != i)
        others.push_back(curves[j]);
    return crack_tips(
      curve,
      {{&domain.triangulation(regions_and_layers.regions_of(i)[0]),
        &domain.triangulation(regions_and_layers.regions_of(i)[1])}},
      scene.fracture.support_radius,
      i,
      others,
      material_faces);
  }


  std::string
  Model::support_refusal(const CrackSet &crack, const unsigned int i) const
  {
    // A given support radius must stay below the free distance of every
    // tip of the new crack (crack_tips() refuses it otherwise).
    if (!(scene.fracture.support_radius > 0))
      return "";
    InterfaceCurve curve = domain.interface_curves()[i];
    curve.set_crack(crack);
    try
      {
        tips_on(curve, i, ply_boundaries());
      }
    catch (const ExceptionBase &e)
      {
        return "Fracture/Support radius no longer fits: " + one_line_message(e);
      }
    return "";
  }


  void
  Model::check_supports(const CycleRecord &record)
  {
    const bool rectangle =
      scene.geometry.gmsh_file.empty() && scene.mesh.mesh_files.empty();
    const bool uniform = scene.mesh.refinement != Refinement::adaptive;
    // Cycles after this one, each halving the cells under uniform
    // refinement.
    const unsigned int n_later =
      !fixed_meshes && scene.mesh.n_cycles > record.cycle + 1 ?
        scene.mesh.n_cycles - record.cycle - 1 :
        0;
    unresolved_tips.assign(crack_tips_found.size(), "");
    tip_cell_sizes.assign(crack_tips_found.size(), 0.);
    for (unsigned int t = 0; t < crack_tips_found.size(); ++t)
      {
        const CrackTip &tip = crack_tips_found[t];
        if (!tip.defined())
          continue;
        // On the meshes of the subproblems (the later states of a study on
        // one mesh), from their cell extents.
        // (The two regions of the tip's interface.)
        const auto &regions = regions_and_layers.regions_of(tip.interface);
        const ElasticSubproblem *const minus =
          subproblems[regions_and_layers.index(Layer::first, regions[0])].get();
        const ElasticSubproblem *const plus =
          subproblems[regions_and_layers.index(Layer::first, regions[1])].get();
        const TipCells cells =
          minus != nullptr && plus != nullptr ?
            support_cells(tip,
                          {{&minus->cell_extents(), &plus->cell_extents()}}) :
            support_cells(tip,
                          {{&domain.triangulation(regions[0]),
                            &domain.triangulation(regions[1])}});
        tip_cell_sizes[t] = cells.size;
        const double R    = tip.support_radius;
        if (support_holds(R, cells.size))
          continue;
        const double last_size =
          uniform ? std::ldexp(cells.size, -int(n_later)) : cells.size;
        const bool         last_resolved = support_holds(R, last_size);
        std::ostringstream m;
        m << std::setprecision(3);
        if (scene.fracture.support_radius > 0)
          m << "Fracture/Support radius = " << R;
        else
          m << "the automatic support radius R = " << R
            << " (Fracture/Support radius = 0: half the distance "
            << tip.free_distance << " to the nearest obstacle of theta)";
        m << " at the crack tip at "
          << tip_position(tip, scene.geometry.gmsh_file.empty()) << " holds "
          << R / cells.size << " cells of the mesh of "
          << (rectangle ?
                std::string(regions[cells.mesh] == 0 ? "Omega-" : "Omega+") :
                gmsh_region_name(regions[cells.mesh]))
          << " along its radius (cells of size " << cells.size
          << " at the tip on cycle " << record.cycle;
        if (uniform && n_later > 0)
          m << ", " << last_size << " on the last cycle";
        m << "): G needs at least " << min_cells_per_support_radius
          << " (R >= the cell size, else G tends to 0 with R)";
        // The remedies: a larger radius where the obstacles allow it, or
        // cells no larger than R at the tip.
        std::vector<std::string> remedies;
        const double             needed =
          min_cells_per_support_radius * (uniform ? last_size : cells.size);
        if (needed < tip.free_distance)
          {
            std::ostringstream r;
            r << std::setprecision(3) << "Fracture/Support radius in ["
              << needed << ", " << tip.free_distance << ")";
            remedies.push_back(r.str());
          }
        if (rectangle)
          {
            std::ostringstream r;
            r << "at least "
              << std::ceil(scene.mesh.cells_along_sigma *
                           (uniform ? last_size : cells.size) / R)
              << " Mesh/Cells along Sigma"
              << (scene.mesh.cells_along_sigma_plus > 0 ?
                    " (and on the plus side in proportion)" :
                    "")
              << (uniform ? "" : " or more adaptive cycles");
            remedies.push_back(r.str());
          }
        else
          remedies.push_back(uniform ? "more Mesh/Number of cycles" :
                                       "more adaptive cycles");
        m << ": use ";
        for (unsigned int i = 0; i < remedies.size(); ++i)
          m << (i == 0 ? "" : ", or ") << remedies[i];
        // A given radius under uniform refinement: the last cycle is known
        // now; refuse the scene before anything is computed if it cannot
        // hold the support. (The automatic radius: G is not reported at
        // this tip on this cycle, the run goes on; G is a by-product of
        // every scene with a crack, coarse meshes included.)
        AssertThrow(!(scene.fracture.support_radius > 0 &&
                      (record.cycle == 0 || fixed_meshes) && uniform &&
                      !last_resolved),
                    ExcMessage(m.str()));
        unresolved_tips[t] = m.str();
      }
  }


  std::vector<Segment>
  Model::ply_boundaries() const
  {
    // The faces between plies of different materials, of every layer in
    // every region.
    std::vector<Segment> material_faces;
    for (const Layer layer : scene.materials.layers())
      for (const unsigned int r :
           Layout::indices(regions_and_layers.n_regions()))
        if (scene.materials.has_layer(layer) &&
            scene.materials.n_plies(layer) > 1)
          {
            const PlyLaws laws(
              scene.materials.ply_materials(layer, Topology::material_side(r)),
              scene.materials.division(layer));
            const auto faces =
              material_boundaries(domain.triangulation(r), laws);
            material_faces.insert(material_faces.end(),
                                  faces.begin(),
                                  faces.end());
          }
    return material_faces;
  }
} // namespace bilayer
