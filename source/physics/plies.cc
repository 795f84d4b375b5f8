#include <bilayer/physics/plies.h>

#include <algorithm>

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
                   const std::vector<double>        &heights)
    : heights(heights)
  {
    Assert(materials.size() == heights.size() + 1, ExcInternalError());
    for (const LayerMaterial &m : materials)
      laws.push_back(make_elastic_law(m));
  }


  unsigned int
  PlyLaws::ply_on_boundary(const Triangulation<2>  &tria,
                           const types::boundary_id id) const
  {
    if (laws.size() > 1)
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == id)
            return ply(*cell);
    return 0;
  }


  bool
  PlyLaws::uniform_energy_norm_scale() const
  {
    for (const auto &law : laws)
      if (law->energy_norm_scale() != laws[0]->energy_norm_scale())
        return false;
    return true;
  }


  PlyVolumeLoad::PlyVolumeLoad(std::vector<std::unique_ptr<VolumeLoad>> loads,
                               const std::vector<double>               &heights)
    : loads(std::move(loads))
    , heights(heights)
  {
    Assert(this->loads.size() == heights.size() + 1, ExcInternalError());
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
