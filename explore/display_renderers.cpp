#include "explore/display_renderers.h"

#include "scene/area_light.h"

#include <algorithm>

namespace m3055::explore {

void defer_compiles(Renderer& renderer) {
    renderer.set_defer_compiles(true);
    renderer.warm_up_general_programs();
}

int PreviewScale::divisor() const {
    int divisor = 1;
    while (divisor < kMaxPreviewDivisor && full_size_ms_ / double(divisor * divisor) > kPreviewBudgetMs) ++divisor;
    return divisor;
}

void PreviewScale::note(double ms, int divisor) { full_size_ms_ = ms * double(divisor * divisor); }

void render_displays(const Explorer& e, Renderer& a, Renderer& b, int divisor) {
    a.set_area_sampling(kFastSampling);
    a.render_reduced(e.doc.scene, preview_differs(e.doc.scene) ? divisor : 1);
    if (!e.view.compare) return;
    const Scene compare = compare_scene(e);
    b.set_area_sampling(kFastSampling);
    b.render_reduced(compare, preview_differs(compare) ? divisor : 1);
}

bool preview_differs(const Scene& scene) {
    return std::any_of(scene.lights.begin(), scene.lights.end(),
                       [](const Light& light) { return reaches_shader(light) && is_area_light(light.type); });
}

void refine_displays(const Explorer& e, Renderer& a, Renderer& b) {
    a.set_area_sampling(kRenderSampling);
    a.render_specialized(e.doc.scene);
    if (!e.view.compare) return;
    b.set_area_sampling(kRenderSampling);
    b.render_specialized(compare_scene(e));
}

std::size_t deferred_programs(const Renderer& a, const Renderer& b) {
    return a.deferred_programs() + b.deferred_programs();
}

void refine_region(const Explorer& e, Renderer& a, Renderer& b, const DisplayRegion& region, AreaSampling sampling) {
    a.set_area_sampling(sampling);
    a.render_region(e.doc.scene, region);
    if (!e.view.compare) return;
    b.set_area_sampling(sampling);
    b.render_region(compare_scene(e), region);
}

bool render_specialized_when_idle(const Explorer& e, Renderer& a, Renderer& b) {
    if (a.deferred_programs() > 0) a.render_specialized(e.doc.scene);
    else if (b.deferred_programs() > 0) b.render_specialized(compare_scene(e));
    else return false;
    return true;
}

}  // namespace m3055::explore
