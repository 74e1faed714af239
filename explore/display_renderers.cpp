#include "explore/display_renderers.h"

namespace m3055::explore {

void defer_compiles(Renderer& renderer) {
    renderer.set_defer_compiles(true);
    renderer.warm_up_general_programs();
}

void render_displays(const Explorer& e, Renderer& a, Renderer& b) {
    a.render(e.doc.scene);
    if (e.view.compare) b.render(compare_scene(e));
}

std::size_t deferred_programs(const Renderer& a, const Renderer& b) {
    return a.deferred_programs() + b.deferred_programs();
}

bool render_specialized_when_idle(const Explorer& e, Renderer& a, Renderer& b) {
    if (a.deferred_programs() > 0) a.render_specialized(e.doc.scene);
    else if (b.deferred_programs() > 0) b.render_specialized(compare_scene(e));
    else return false;
    return true;
}

}  // namespace m3055::explore
