#include <bilayer/physics/plies.h>

#include <algorithm>
#include <limits>

namespace bilayer
{
  using namespace dealii;


  unsigned int
  ply_of(const std::vector<double> &heights, const double y)
  {
    return std::lower_bound(heights.begin(), heights.end(), y) -
           heights.begin();
  }


  PlyLaws::PlyLaws(const std::vector<LayerMaterial> &materials,
                   const PlyDivision                &division)
    : materials(materials)
    , division(division)
  {
    Assert(materials.size() == 1 || division.by_material_id.size() > 0 ||
             materials.size() == division.heights.size() + 1,
           ExcInternalError());
    for (const LayerMaterial &m : materials)
      laws.push_back(make_elastic_law(m));
  }


  unsigned int
  PlyLaws::ply_on_boundary(const Triangulation<2>  &tria,
                           const types::boundary_id id,
                           const Point<2>          *point) const
  {
    if (laws.size() == 1)
      return 0;
    double       nearest = std::numeric_limits<double>::infinity();
    unsigned int found   = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          {
            if (point == nullptr)
              return ply(*cell);
            const double d = face->center().distance(*point);
            if (d < nearest)
              nearest = d, found = ply(*cell);
          }
    return found;
  }


  bool
  PlyLaws::differ(const unsigned int i, const unsigned int j) const
  {
    const Eigenstrain3D a = thermal_strain(materials[i]),
                        b = thermal_strain(materials[j]);
    return laws[i]->tangent() != laws[j]->tangent() ||
           a.in_plane != b.in_plane || a.zz != b.zz;
  }


  bool
  PlyLaws::uniform_energy_norm_scale() const
  {
    for (const auto &law : laws)
      if (law->energy_norm_scale() != laws[0]->energy_norm_scale())
        return false;
    return true;
  }


  std::vector<std::array<Point<2>, 2>>
  material_boundaries(const Triangulation<2> &tria, const PlyLaws &laws)
  {
    std::vector<std::array<Point<2>, 2>> faces;
    if (laws.size() > 1)
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f))
            {
              const auto neighbor = cell->neighbor(f);
              // Each face once: from the cell of the smaller level and
              // index (a coarser neighbour's face is seen from this side).
              if (!cell->neighbor_is_coarser(f) &&
                  (neighbor->has_children() ||
                   neighbor->index() < cell->index()))
                continue;
              if (laws.differ(laws.ply(*cell), laws.ply(*neighbor)))
                faces.push_back(
                  {{cell->face(f)->vertex(0), cell->face(f)->vertex(1)}});
            }
    return faces;
  }


  PlyVolumeLoad::PlyVolumeLoad(std::vector<std::unique_ptr<VolumeLoad>> loads,
                               const PlyDivision &division)
    : loads(std::move(loads))
    , division(division)
  {
    Assert(division.by_material_id.size() > 0 ||
             this->loads.size() == division.heights.size() + 1,
           ExcInternalError());
  }


  CellLoad
  PlyVolumeLoad::in(const CellAccessor<2, 2> &cell) const
  {
    return {loads[division.ply(cell)].get(), 1, 1};
  }


  const VolumeLoad *
  PlyVolumeLoad::at(const Point<2> &p) const
  {
    Assert(division.by_material_id.empty(),
           ExcMessage("The load of a ply group is read by cell (in())."));
    return loads[ply_of(division.heights, p[1])].get();
  }


  Tensor<1, 2>
  PlyVolumeLoad::body_force(const Point<2> &p) const
  {
    const VolumeLoad *load = at(p);
    return load ? load->body_force(p) : Tensor<1, 2>();
  }


  SymmetricTensor<2, 2>
  PlyVolumeLoad::eigenstrain(const Point<2> &p) const
  {
    const VolumeLoad *load = at(p);
    return load ? load->eigenstrain(p) : SymmetricTensor<2, 2>();
  }


  double
  PlyVolumeLoad::eigenstress_zz(const Point<2> &p) const
  {
    const VolumeLoad *load = at(p);
    return load ? load->eigenstress_zz(p) : 0.;
  }


  bool
  PlyVolumeLoad::has_body_force() const
  {
    return std::any_of(loads.begin(), loads.end(), [](const auto &load) {
      return load && load->has_body_force();
    });
  }


  bool
  PlyVolumeLoad::has_eigenstrain() const
  {
    return std::any_of(loads.begin(), loads.end(), [](const auto &load) {
      return load && load->has_eigenstrain();
    });
  }


  double
  PlyVolumeLoad::length_scale() const
  {
    for (const auto &load : loads)
      if (load)
        return load->length_scale();
    return 1;
  }


  Tensor<2, 2>
  PlyVolumeLoad::body_force_gradient(const Point<2> &p) const
  {
    const VolumeLoad *load = at(p);
    return load ? load->body_force_gradient(p) : Tensor<2, 2>();
  }


  std::array<SymmetricTensor<2, 2>, 2>
  PlyVolumeLoad::eigenstrain_gradient(const Point<2> &p) const
  {
    const VolumeLoad *load = at(p);
    return load ? load->eigenstrain_gradient(p) :
                  std::array<SymmetricTensor<2, 2>, 2>();
  }
} // namespace bilayer
