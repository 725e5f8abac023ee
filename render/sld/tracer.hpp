// The min-rt tracer: the class (tracer_class.hpp) and its member functions,
// one file per seam of the algorithm.
#pragma once

#include "render/sld/tracer_class.hpp"

#include "render/sld/scene_setup.hpp"
#include "render/sld/solvers.hpp"
#include "render/sld/direction_tables.hpp"
#include "render/sld/networks.hpp"
#include "render/sld/normals_textures.hpp"
#include "render/sld/direct_light.hpp"
#include "render/sld/diffuse_light.hpp"
#include "render/sld/band_rows.hpp"
#include "render/sld/mirrors.hpp"
