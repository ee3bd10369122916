// SPDX-License-Identifier: Apache-2.0
// Makes the silhouettes of bench/collage-shapes/ (issue 15): some traced from the photographs and
// drawings that Debian's opencv-doc package ships, some drawn here by hand, stroke by stroke.
// Every shape is written as an 8-bit grey PNG, black shape on white, at most 320 pixels a side.
//   build/release/bench/make_collage_shapes /usr/share/doc/opencv-doc/examples/data
//   bench/collage-shapes
// The PNGs are checked in: the benchmark does not need this program or opencv-doc to run.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace {

namespace fs = std::filesystem;

cv::Mat read(const fs::path& path, int flags = cv::IMREAD_COLOR) {
  cv::Mat m = cv::imread(path.string(), flags);
  if (m.empty()) throw std::runtime_error(path.string() + ": cannot read");
  return m;
}

// The connected components of `mask` (8-connected) whose area is at least `min_area`.
cv::Mat keep_components(const cv::Mat& mask, int min_area) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  cv::Mat out(mask.size(), CV_8UC1, cv::Scalar(0));
  for (int k = 1; k < n; ++k)
    if (stats.at<int>(k, cv::CC_STAT_AREA) >= min_area) out.setTo(255, labels == k);
  return out;
}

cv::Mat largest_component(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  int best = 1;
  for (int k = 2; k < n; ++k)
    if (stats.at<int>(k, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA)) best = k;
  return labels == best;
}

// Fills the holes of `mask` smaller than `max_area` pixels (all holes when max_area ≤ 0).
cv::Mat fill_holes(const cv::Mat& mask, int max_area = 0) {
  cv::Mat background = mask == 0;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(background, labels, stats, centroids, 4);
  cv::Mat out = mask.clone();
  for (int k = 1; k < n; ++k) {
    const int x = stats.at<int>(k, cv::CC_STAT_LEFT), y = stats.at<int>(k, cv::CC_STAT_TOP);
    const int w = stats.at<int>(k, cv::CC_STAT_WIDTH), h = stats.at<int>(k, cv::CC_STAT_HEIGHT);
    const bool touches_border = x == 0 || y == 0 || x + w == mask.cols || y + h == mask.rows;
    if (touches_border) continue;
    if (max_area <= 0 || stats.at<int>(k, cv::CC_STAT_AREA) < max_area) out.setTo(255, labels == k);
  }
  return out;
}

cv::Mat morph(const cv::Mat& mask, int op, int radius) {
  const cv::Mat disc =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * radius + 1, 2 * radius + 1});
  cv::Mat out;
  cv::morphologyEx(mask, out, op, disc);
  return out;
}

// Crops the mask to its bounding box plus a 6% margin, scales the longer side to `side` pixels
// and writes it black on white.
void write_shape(const fs::path& folder, const std::string& name, const cv::Mat& mask,
                 int side = 320) {
  const cv::Rect box = cv::boundingRect(mask);
  const int pad = static_cast<int>(0.06 * std::max(box.width, box.height));
  cv::Mat framed(box.height + 2 * pad, box.width + 2 * pad, CV_8UC1, cv::Scalar(0));
  mask(box).copyTo(framed(cv::Rect(pad, pad, box.width, box.height)));
  const double k = static_cast<double>(side) / std::max(framed.cols, framed.rows);
  cv::Mat scaled;
  cv::resize(framed, scaled, {}, k, k, k < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  cv::Mat shape = scaled > 127;
  cv::Mat out = 255 - shape;
  const fs::path path = folder / (name + ".png");
  if (!cv::imwrite(path.string(), out)) throw std::runtime_error(path.string() + ": cannot write");
  std::printf("%s: %dx%d, %d shape pixels\n", path.c_str(), out.cols, out.rows,
              cv::countNonZero(shape));
}

// --- Traced from photographs and drawings -------------------------------------------------

// Hue (0..179), saturation and value of a colour image, one 8-bit channel each.
std::vector<cv::Mat> hsv_channels(const fs::path& path) {
  cv::Mat hsv;
  cv::cvtColor(read(path), hsv, cv::COLOR_BGR2HSV);
  std::vector<cv::Mat> channels;
  cv::split(hsv, channels);
  return channels;
}

// HappyFish.jpg, a cartoon fish: every pixel that is coloured or dark (not the white ground), the
// largest component (the bubbles go), holes filled (the eye).
cv::Mat fish(const fs::path& data) {
  const auto c = hsv_channels(data / "HappyFish.jpg");
  const cv::Mat ink = (c[1] > 60) | (c[2] < 200);
  return fill_holes(morph(largest_component(morph(ink, cv::MORPH_OPEN, 1)), cv::MORPH_CLOSE, 2));
}

// butterfly.jpg, a swallowtail photographed from above: its black wings and body (dark and
// unsaturated), the largest component; the white spots of the wings stay as holes, except those
// of a few pixels.
cv::Mat butterfly(const fs::path& data) {
  const auto c = hsv_channels(data / "butterfly.jpg");
  cv::Mat dark = c[2] < 80;
  dark = morph(dark, cv::MORPH_CLOSE, 2);
  return fill_holes(morph(largest_component(dark), cv::MORPH_OPEN, 1), 60);
}

// opencv-logo.png: the opaque pixels of the top part (three open rings) or of the word below it.
cv::Mat logo_alpha(const fs::path& data) {
  const cv::Mat bgra = read(data / "opencv-logo.png", cv::IMREAD_UNCHANGED);
  cv::Mat alpha;
  cv::extractChannel(bgra, alpha, 3);
  return alpha > 127;
}

cv::Mat logo_rings(const fs::path& data) {
  cv::Mat mask = logo_alpha(data);
  mask(cv::Rect(0, 600, mask.cols, mask.rows - 600)).setTo(0);
  return mask;
}

// Letters `first` and `first + 1` (0-based, left to right) of the word "OpenCV" under the logo.
cv::Mat logo_letters(const fs::path& data, int first) {
  cv::Mat mask = logo_alpha(data);
  mask(cv::Rect(0, 0, mask.cols, 600)).setTo(0);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  std::vector<std::pair<int, int>> by_x;  // (left, label)
  for (int k = 1; k < n; ++k)
    if (stats.at<int>(k, cv::CC_STAT_AREA) > 200)
      by_x.emplace_back(stats.at<int>(k, cv::CC_STAT_LEFT), k);
  std::sort(by_x.begin(), by_x.end());
  if (static_cast<int>(by_x.size()) < first + 2)
    throw std::runtime_error("opencv-logo.png: fewer letters than expected");
  cv::Mat out(mask.size(), CV_8UC1, cv::Scalar(0));
  for (int i = first; i < first + 2; ++i)
    out.setTo(255, labels == by_x[static_cast<std::size_t>(i)].second);
  return out;
}

// smarties.png, sweets on a white sheet: the saturated pixels of the upper-right part, where five
// sweets lie whole.
cv::Mat sweets(const fs::path& data) {
  const auto c = hsv_channels(data / "smarties.png");
  cv::Mat mask = (c[1] > 90) | (c[2] < 90);
  mask = fill_holes(morph(mask, cv::MORPH_OPEN, 2));
  cv::Mat crop(mask.size(), CV_8UC1, cv::Scalar(0));
  const cv::Rect keep(170, 40, mask.cols - 170, 240);
  mask(keep).copyTo(crop(keep));
  return keep_components(crop, 400);
}

// apple.jpg: the red, saturated pixels; the largest component with its stem's dark neighbour
// closed in, holes (the highlights) filled, the pencil under it opened away.
cv::Mat apple(const fs::path& data) {
  const auto c = hsv_channels(data / "apple.jpg");
  cv::Mat red = ((c[0] < 15) | (c[0] > 165)) & (c[1] > 80) & (c[2] > 40);
  red = morph(morph(red, cv::MORPH_CLOSE, 6), cv::MORPH_OPEN, 4);
  return fill_holes(largest_component(red));
}

// --- Drawn by hand -----------------------------------------------------------------------------

void stroke(cv::Mat& m, cv::Point a, cv::Point b, int width) {
  cv::line(m, a, b, cv::Scalar(255), width, cv::LINE_AA);
}

// An open right hand seen from the palm: palm and wrist, four fingers of different lengths and
// slants, a thumb bent at its joint.
cv::Mat hand() {
  cv::Mat m(340, 260, CV_8UC1, cv::Scalar(0));
  const std::vector<cv::Point> palm = {{84, 300},  {166, 300}, {182, 238}, {186, 168},
                                       {160, 150}, {96, 152},  {74, 170},  {70, 222}};
  cv::fillPoly(m, std::vector<std::vector<cv::Point>>{palm}, cv::Scalar(255), cv::LINE_AA);
  cv::rectangle(m, {92, 290}, {160, 336}, cv::Scalar(255), cv::FILLED);
  stroke(m, {92, 168}, {80, 96}, 25);     // index
  stroke(m, {80, 96}, {76, 62}, 22);      // its last joint, bent a little
  stroke(m, {122, 160}, {124, 44}, 26);   // middle
  stroke(m, {150, 164}, {160, 58}, 24);   // ring
  stroke(m, {174, 180}, {198, 104}, 20);  // little finger
  stroke(m, {80, 250}, {44, 206}, 30);    // thumb, base
  stroke(m, {44, 206}, {30, 160}, 25);    // thumb, tip
  return m > 127;
}

// A broad-leaved tree: a trunk flaring into roots, forking into three limbs, each carrying a
// cluster of leafy lobes with sky between the clusters.
cv::Mat tree() {
  cv::Mat m(320, 300, CV_8UC1, cv::Scalar(0));
  const std::vector<cv::Point> trunk = {{118, 312}, {136, 290}, {140, 200},
                                        {160, 200}, {164, 290}, {186, 312}};
  cv::fillPoly(m, std::vector<std::vector<cv::Point>>{trunk}, cv::Scalar(255), cv::LINE_AA);
  stroke(m, {148, 210}, {86, 132}, 16);   // left limb
  stroke(m, {152, 210}, {218, 122}, 15);  // right limb
  stroke(m, {150, 205}, {146, 96}, 15);   // middle limb
  stroke(m, {100, 150}, {60, 150}, 8);    // a twig on the left
  const cv::Scalar on(255);
  // Left cluster.
  cv::ellipse(m, {78, 118}, {44, 34}, -10, 0, 360, on, cv::FILLED, cv::LINE_AA);
  cv::ellipse(m, {44, 140}, {26, 20}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);
  cv::ellipse(m, {96, 92}, {30, 24}, 15, 0, 360, on, cv::FILLED, cv::LINE_AA);
  // Middle cluster, the highest.
  cv::ellipse(m, {144, 70}, {44, 40}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);
  cv::ellipse(m, {124, 40}, {26, 22}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);
  cv::ellipse(m, {168, 44}, {28, 24}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);
  // Right cluster.
  cv::ellipse(m, {222, 110}, {46, 36}, 12, 0, 360, on, cv::FILLED, cv::LINE_AA);
  cv::ellipse(m, {256, 134}, {26, 20}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);
  cv::ellipse(m, {206, 84}, {26, 22}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);
  return m > 127;
}

// An old door key, tilted: a round bow with a hole, a shaft, a bit with two wards cut in it.
cv::Mat key() {
  cv::Mat m(200, 340, CV_8UC1, cv::Scalar(0));
  const cv::Scalar on(255), off(0);
  cv::circle(m, {70, 100}, 52, on, cv::FILLED, cv::LINE_AA);
  cv::circle(m, {70, 100}, 26, off, cv::FILLED, cv::LINE_AA);  // the hole
  cv::rectangle(m, {112, 88}, {310, 112}, on, cv::FILLED);     // shaft
  cv::rectangle(m, {250, 112}, {306, 166}, on, cv::FILLED);    // bit
  cv::rectangle(m, {264, 134}, {274, 166}, off, cv::FILLED);   // wards
  cv::rectangle(m, {286, 112}, {294, 148}, off, cv::FILLED);
  cv::Mat tilted;
  const cv::Mat turn = cv::getRotationMatrix2D({170, 100}, 18, 1.0);
  cv::warpAffine(m, tilted, turn, m.size(), cv::INTER_LINEAR);
  return tilted > 127;
}

// A cat sitting, seen from the side: body and haunch, a neck into a round head with two pointed
// ears, two front legs, a tail curling up behind (added after the fitter's work on issue 32, to
// check it on animals it was not tuned to).
cv::Mat cat() {
  cv::Mat m(330, 300, CV_8UC1, cv::Scalar(0));
  const cv::Scalar on(255);
  cv::ellipse(m, {150, 222}, {66, 80}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);   // body
  cv::ellipse(m, {178, 262}, {58, 52}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);   // haunch
  cv::ellipse(m, {128, 160}, {38, 44}, 20, 0, 360, on, cv::FILLED, cv::LINE_AA);  // neck
  cv::circle(m, {118, 108}, 46, on, cv::FILLED, cv::LINE_AA);                     // head
  const std::vector<std::vector<cv::Point>> ears = {{{80, 88}, {84, 36}, {112, 68}},
                                                    {{124, 64}, {152, 30}, {158, 82}}};
  cv::fillPoly(m, ears, on, cv::LINE_AA);
  stroke(m, {112, 236}, {108, 312}, 22);  // front legs
  stroke(m, {142, 246}, {142, 312}, 20);
  stroke(m, {222, 296}, {262, 260}, 16);  // tail
  stroke(m, {262, 260}, {272, 200}, 14);
  stroke(m, {272, 200}, {256, 160}, 12);
  return m > 127;
}

// A bird in flight, wings raised: body, head and beak, two wings and a forked tail.
cv::Mat bird() {
  cv::Mat m(250, 340, CV_8UC1, cv::Scalar(0));
  const cv::Scalar on(255);
  cv::ellipse(m, {170, 150}, {72, 28}, -8, 0, 360, on, cv::FILLED, cv::LINE_AA);  // body
  cv::circle(m, {242, 132}, 23, on, cv::FILLED, cv::LINE_AA);                     // head
  const std::vector<std::vector<cv::Point>> parts = {
      {{260, 124}, {296, 134}, {260, 142}},            // beak
      {{128, 142}, {58, 36}, {112, 58}, {176, 134}},   // far wing
      {{168, 136}, {204, 22}, {222, 56}, {206, 140}},  // near wing
      {{108, 152}, {44, 122}, {66, 156}, {46, 186}}};  // forked tail
  cv::fillPoly(m, parts, on, cv::LINE_AA);
  return m > 127;
}

// A dog standing, seen from the side: a long body, a deep chest, a neck rising to a head with a
// muzzle and a drooping ear, four legs (the far ones a step behind the near ones) and a tail
// raised in a curve (added after the fitter's sixth issue-32 pass, before its seventh, to check
// it on an animal it was not tuned to).
cv::Mat dog() {
  cv::Mat m(300, 360, CV_8UC1, cv::Scalar(0));
  const cv::Scalar on(255);
  cv::ellipse(m, {180, 150}, {96, 42}, -4, 0, 360, on, cv::FILLED, cv::LINE_AA);  // body
  cv::ellipse(m, {112, 160}, {40, 46}, 0, 0, 360, on, cv::FILLED, cv::LINE_AA);   // chest
  cv::ellipse(m, {90, 104}, {26, 46}, 30, 0, 360, on, cv::FILLED, cv::LINE_AA);   // neck
  cv::circle(m, {72, 64}, 28, on, cv::FILLED, cv::LINE_AA);                       // head
  cv::ellipse(m, {38, 78}, {30, 13}, 8, 0, 360, on, cv::FILLED, cv::LINE_AA);     // muzzle
  const std::vector<cv::Point> ear = {{78, 40}, {96, 42}, {98, 84}, {86, 86}};    // drooping
  cv::fillPoly(m, std::vector<std::vector<cv::Point>>{ear}, on, cv::LINE_AA);
  stroke(m, {104, 186}, {98, 282}, 20);   // near front leg
  stroke(m, {130, 186}, {132, 278}, 16);  // far front leg
  stroke(m, {238, 168}, {252, 222}, 26);  // near hind leg: thigh
  stroke(m, {252, 222}, {240, 282}, 18);  // its shank
  stroke(m, {212, 170}, {214, 278}, 16);  // far hind leg
  stroke(m, {268, 136}, {304, 96}, 12);   // tail
  stroke(m, {304, 96}, {314, 52}, 10);
  return m > 127;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc != 3) {
    std::fprintf(stderr, "usage: make_collage_shapes OPENCV_DOC_DATA_FOLDER OUTPUT_FOLDER\n");
    return 2;
  }
  const fs::path data = argv[1], out = argv[2];
  write_shape(out, "fish", fish(data));
  write_shape(out, "butterfly", butterfly(data));
  write_shape(out, "rings", logo_rings(data));
  write_shape(out, "logo", logo_alpha(data));
  write_shape(out, "letters-cv", logo_letters(data, 4));
  write_shape(out, "letters-op", logo_letters(data, 0));
  write_shape(out, "sweets", sweets(data));
  write_shape(out, "apple", apple(data));
  write_shape(out, "hand", hand());
  write_shape(out, "tree", tree());
  write_shape(out, "key", key());
  write_shape(out, "cat", cat());
  write_shape(out, "bird", bird());
  write_shape(out, "dog", dog());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "make_collage_shapes: %s\n", e.what());
  return 1;
}
