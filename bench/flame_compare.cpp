// SPDX-License-Identifier: Apache-2.0
// Similarity of two pictures of the same size, for bench/flame_vs_flam3.sh:
//   flame_compare A.png B.png   →   "ssim S colour C"
// S: SSIM of the luminances (Wang et al. 2004: Gaussian window σ = 1.5, K1 = 0.01, K2 = 0.03,
// on 0…255), averaged over the picture; C: the mean over pixels of the Euclidean distance of the
// RGB colours, 0…255 per channel.
#include <cmath>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace {

double ssim(const cv::Mat& a, const cv::Mat& b) {
  const double c1 = std::pow(0.01 * 255, 2), c2 = std::pow(0.03 * 255, 2);
  const auto blur = [](const cv::Mat& m) {
    cv::Mat out;
    cv::GaussianBlur(m, out, cv::Size(11, 11), 1.5);
    return out;
  };
  const cv::Mat mu_a = blur(a), mu_b = blur(b);
  const cv::Mat aa = blur(a.mul(a)) - mu_a.mul(mu_a), bb = blur(b.mul(b)) - mu_b.mul(mu_b);
  const cv::Mat ab = blur(a.mul(b)) - mu_a.mul(mu_b);
  cv::Mat num = (2 * mu_a.mul(mu_b) + c1).mul(2 * ab + c2);
  cv::Mat den = (mu_a.mul(mu_a) + mu_b.mul(mu_b) + c1).mul(aa + bb + c2);
  cv::Mat map;
  cv::divide(num, den, map);
  return cv::mean(map)[0];
}

cv::Mat luminance(const cv::Mat& bgr) {
  cv::Mat grey, out;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(out, CV_64F);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    fmt::print(stderr, "usage: flame_compare A.png B.png\n");
    return 2;
  }
  const cv::Mat a = cv::imread(argv[1], cv::IMREAD_COLOR),
                b = cv::imread(argv[2], cv::IMREAD_COLOR);
  if (a.empty() || b.empty() || a.size() != b.size()) {
    fmt::print(stderr, "flame_compare: {} and {}: two readable pictures of one size are needed\n",
               argv[1], argv[2]);
    return 2;
  }
  cv::Mat fa, fb, d;
  a.convertTo(fa, CV_64FC3);
  b.convertTo(fb, CV_64FC3);
  cv::Mat diff = fa - fb;
  d = diff.mul(diff);
  cv::Mat dist(d.size(), CV_64F);
  for (int r = 0; r < d.rows; ++r)
    for (int c = 0; c < d.cols; ++c) {
      const cv::Vec3d v = d.at<cv::Vec3d>(r, c);
      dist.at<double>(r, c) = std::sqrt(v[0] + v[1] + v[2]);
    }
  fmt::print("ssim {:.4f} colour {:.3f}\n", ssim(luminance(a), luminance(b)), cv::mean(dist)[0]);
  return 0;
}
