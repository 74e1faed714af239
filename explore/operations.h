// The document's commands (explore/commands.h): each turns what was asked
// into one typed edit of the document (explore/edits.h), which names the
// undo step and asks for one render, and moves the view's selection with
// it. Called by explore/apply.cpp, the one place commands are applied.
// Each returns whether it did what was asked; a reason it could not goes to
// explorer.session.messages.error where the user should see it.
#pragma once

#include "explore/commands.h"
#include "explore/explorer.h"

#include <string>

namespace m3055::explore {

inline constexpr int kMaxExplorerLights = 8;
// The names of two buttons' edits.
inline constexpr const char* kEq14Action = "rescale weights to eq. 14";
inline constexpr const char* kFresnelPresetAction = "A/B preset: F(lambda, 0) vs full eq. 19";

// Records `edit` as the user's: the status line's last action gives way to
// it and the displays are drawn again. Returns whether the document changed.
bool edit_document(Explorer& explorer, Edit edit);

bool apply(Explorer& explorer, const command::SetMaterial& c);
bool apply(Explorer& explorer, const command::SetLight& c);
bool apply(Explorer& explorer, const command::ApplyLightPreset& c);
bool apply(Explorer& explorer, const command::AddLight& c);
bool apply(Explorer& explorer, const command::RemoveLight& c);
bool apply(Explorer& explorer, const command::SetObject& c);
bool apply(Explorer& explorer, const command::AddObject& c);
bool apply(Explorer& explorer, const command::RemoveObject& c);
bool apply(Explorer& explorer, const command::MoveObjectInView& c);
bool apply(Explorer& explorer, const command::SetCamera& c);
bool apply(Explorer& explorer, const command::OrbitCamera& c);
bool apply(Explorer& explorer, const command::ZoomCamera& c);
bool apply(Explorer& explorer, const command::ResetCamera& c);
bool apply(Explorer& explorer, const command::SetDisplay& c);
bool apply(Explorer& explorer, const command::SetBackground& c);
bool apply(Explorer& explorer, const command::SetSceneValue& c);  // throws SceneError with the loader's message
bool apply(Explorer& explorer, const command::CopyAToB& c);
bool apply(Explorer& explorer, const command::CompareFresnel& c);
bool apply(Explorer& explorer, const command::SetCompare& c);
bool apply(Explorer& explorer, const command::Undo& c);
bool apply(Explorer& explorer, const command::Redo& c);

// ---- What the widgets, keys and script compute before they ask ---------------------------
// The selected object's material switched to model `name` (values with the
// same name and meaning kept: with_model); std::runtime_error for a name not
// in the table or with no object.
Material with_model_named(const Material& material, const std::string& name);
// The selected material with its metal's weights rescaled to eq. 14; false when not possible.
bool eq14_rescaled(const Material& material, Material* rescaled);
// The M3055 (512 x 320, 5 bits), and a "modern" display of the given size at 8 bits.
Display m3055_display(const Display& from);
Display modern_display(const Display& from, int width, int height);

// Commits the edits in progress as one undo step (the frame loop, when no
// widget or drag is in progress). Returns whether there were any.
bool commit_edits(Explorer& explorer);

}  // namespace m3055::explore
