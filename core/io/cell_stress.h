#pragma once
// The stress in each cell of a solved model, at the cell's centre (Q1: reference point (0, 0);
// P1: constant), for the results files and the VTU (SPEC §4: "the stress per cell").
#include <Eigen/Core>

#include "core/fem/model.h"

namespace thinlayer {

// One row per cell, bodies in order and, within a body, quads then triangles (the order of
// SceneRecord::cells): (σ11, σ22, σ12) in daN/mm². `u_full` holds (u1, u2) per node of all
// bodies in order, mm.
Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> cell_stresses(const Model& model,
                                                                        const Eigen::VectorXd& u_full);

}  // namespace thinlayer
