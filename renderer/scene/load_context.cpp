#include "scene/load_context.h"

#include "scene/json_brdf.h"

namespace m3055 {

LoadContext LoadContext::trusted() { return {}; }

LoadContext LoadContext::for_class(bool allow_code) {
    LoadContext context;
    if (!allow_code) context.code_refused = scene_json::brdf_not_allowed_reason();
    return context;
}

}  // namespace m3055
