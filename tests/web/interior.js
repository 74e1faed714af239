// The interior pixels of a scene's display, as the reference's tests count
// them (renderer/reference/reference.h, is_interior): a pixel whose 8
// neighbours show the same object (or the background) as itself. Away from
// silhouettes, where two rasterizers may cover a pixel centre that an edge
// passes through differently, the page is held to the area lights' criterion.
'use strict';

// Each object's colour in the coverage scene: levels 0, 1/2 and 1 a channel,
// black left to the background (26 objects).
function coverageColour(i) {
  const n = i + 1;
  if (n > 26) throw new Error('coverage scene: more than 26 objects');
  return [n % 3, Math.floor(n / 3) % 3, Math.floor(n / 9) % 3].map((v) => v / 2);
}

// The scene with every object flat in its own colour on a black background:
// the classic Phong model with only its ambient term (ka), lit by one black
// directional light's ambient, so shading, shadows and area lights drop out
// and only which object covers each pixel is left.
function coverageScene(text) {
  const scene = JSON.parse(text);
  scene.display = { ...scene.display, bits: 8 };  // three levels a channel stay apart at any bits
  scene.background = [0, 0, 0];
  scene.lights = [{ type: 'directional', direction: [0, 1, 0], intensity: 1, color: [0, 0, 0], ambient: [1, 1, 1] }];
  scene.objects = scene.objects.map((o, i) => ({ ...o, material: { model: 'phong', kd: [0, 0, 0], ks: [0, 0, 0], ka: coverageColour(i) } }));
  return JSON.stringify(scene, null, 2);
}

// For a decoded PNG of coverageScene: 1 where the pixel and its 8 neighbours
// (all inside the image) have one colour, else 0.
function interiorMask(coverage) {
  const { width, height, channels, pixels } = coverage;
  const same = (i, j) => pixels[i * channels] === pixels[j * channels] && pixels[i * channels + 1] === pixels[j * channels + 1] &&
    pixels[i * channels + 2] === pixels[j * channels + 2];
  const mask = new Uint8Array(width * height);
  for (let y = 1; y + 1 < height; ++y) {
    for (let x = 1; x + 1 < width; ++x) {
      const i = y * width + x;
      let all = true;
      for (let dy = -1; dy <= 1 && all; ++dy) for (let dx = -1; dx <= 1 && all; ++dx) all = same(i, i + dy * width + dx);
      mask[i] = all ? 1 : 0;
    }
  }
  return mask;
}

module.exports = { coverageScene, interiorMask };
