// The command line's settings applied to a scene: the one place they meet it.
#include "io/scene/scene_sections.hpp"
#include "tridem/scene_io.hpp"

namespace tridem {

Scene apply_overrides(Scene scene, const SceneOverrides& o) {
  if (o.out_dir) scene.output.dir = *o.out_dir;
  if (o.backend) scene.simulation.backend = *o.backend;
  if (o.steps) {  // --steps sets the length, whichever key the scene used
    scene.simulation.steps = *o.steps;
    scene.simulation.duration = 0;
  }
  if (o.method) scene.simulation.method = *o.method;
  if (o.contact_test) scene.simulation.contact_test = *o.contact_test;
  if (o.bbox_prefilter) scene.simulation.bbox_prefilter = *o.bbox_prefilter;
  scene_detail::validate_settings(scene);
  return scene;
}

}  // namespace tridem
