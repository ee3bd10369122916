// SPDX-License-Identifier: Apache-2.0
// The flame reader's fuzz check (see fuzz_checks.h): every flame it reads is one a renderer can
// take (xforms, finite numbers, one value per parameter, a positive total weight), each xform can
// be applied to a few points (the variations under the sanitizers with any parameters: a
// non-finite result is allowed, undefined behaviour is not), and what the writer makes of it
// reads back to the same XML (write ∘ read is idempotent).
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "flame/flame_file.h"
#include "flame/flame_write.h"
#include "flame/variations.h"
#include "flame/xform_eval.h"
#include "ifs/error.h"
#include "tests/fuzz/fuzz_checks.h"

namespace ifsfx::fuzz {

inline void check_renderable(const flame::Xform& xf) {
  for (double v : xf.pre.coefficients()) check(std::isfinite(v), "finite pre-affine coefficients");
  if (xf.post)
    for (double v : xf.post->coefficients()) check(std::isfinite(v), "finite post coefficients");
  check(std::isfinite(xf.weight) && xf.weight >= 0, "a finite weight >= 0");
  for (const auto* list : {&xf.pre_variations, &xf.variations, &xf.post_variations})
    for (const flame::VariationTerm& t : *list) {
      check(t.id < flame::variations().size(), "a variation of the registry");
      check(t.params.size() == flame::variation(t.id).parameters.size(), "one value a parameter");
      check(std::isfinite(t.weight), "a finite variation weight");
    }
  Rng rng(1);
  for (const Point p : {Point{0, 0}, Point{0.3, -0.2}, Point{-2.5, 1e3}}) {
    const Point q = flame::apply_xform(xf, p, rng);
    (void)q;
  }
}

inline void flame_xml(std::string_view text) {
  // No palette library: palette="N" is refused (with an ifsfx::Error), never read from disk.
  const flame::FlameReadOptions options{.palette_file = "/nonexistent/flam3-palettes.xml"};
  std::vector<flame::Flame> flames;
  try {
    flames = flame::parse_flames(text, "fuzz.flame", options);
  } catch (const Error&) {
    return;
  }
  check(!flames.empty(), "a file read has flames");
  double total = 0;
  for (const flame::Flame& f : flames) {
    check(!f.xforms.empty(), "a flame read has xforms");
    for (const flame::Xform& xf : f.xforms) {
      check_renderable(xf);
      total += xf.weight;
    }
    if (f.final_xform) check_renderable(*f.final_xform);
    check(f.camera.width >= 1 && f.camera.height >= 1, "a picture of at least one pixel");
  }
  check(total > 0, "positive weights");
  const std::string once = flame::flames_xml(flames);
  const std::string twice = flame::flames_xml(flame::parse_flames(once, "again.flame", options));
  check(once == twice, "what the writer writes reads back to the same flames");
}

}  // namespace ifsfx::fuzz
