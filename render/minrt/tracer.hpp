// The min-rt tracer: the class (tracer_class.hpp) and its member functions,
// one file per seam of the algorithm.
#pragma once

#include "render/minrt/tracer_class.hpp"

#include "render/minrt/scene_setup.hpp"
#include "render/minrt/solvers.hpp"
#include "render/minrt/direction_tables.hpp"
#include "render/minrt/networks.hpp"
#include "render/minrt/normals_textures.hpp"
#include "render/minrt/direct_light.hpp"
#include "render/minrt/diffuse_light.hpp"
#include "render/minrt/band_rows.hpp"
#include "render/minrt/mirrors.hpp"
