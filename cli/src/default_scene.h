// rast — the built-in default scene: the lecture's cases in one picture.
#pragma once

#include <rast/scene.h>

namespace rast::cli {

Scene default_scene();

}  // namespace rast::cli
