#include "tracker/moschini/visual_hull.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/error.h"
#include "tracker/common/mask_box.h"

namespace simcap::tracker {

Eigen::Vector3i VoxelGrid::index(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d f = (world - origin) / voxel;
  return {static_cast<int>(std::floor(f.x() + 0.5)), static_cast<int>(std::floor(f.y() + 0.5)),
          static_cast<int>(std::floor(f.z() + 0.5))};
}

bool Occupancy::occupied_near(const Eigen::Vector3d& world, int radius) const {
  const Eigen::Vector3i c = grid.index(world);
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dz = -radius; dz <= radius; ++dz) {
      for (int dx = -radius; dx <= radius; ++dx) {
        if (occupied(c + Eigen::Vector3i(dx, dy, dz))) return true;
      }
    }
  }
  return false;
}

VisualHull::VisualHull(std::vector<Camera> cameras, const HullOptions& options)
    : cameras_(std::move(cameras)) {
  const int nc = static_cast<int>(cameras_.size());
  if (nc == 0) throw Error("visual hull: no cameras");
  if (!(options.voxel_m >= 0.002 && options.voxel_m <= 0.5)) {
    throw Error("voxel size must be between 0.002 and 0.5 m, got " +
                std::to_string(options.voxel_m));
  }
  if (options.volume.isEmpty() || !(options.volume.sizes().array() > 0).all()) {
    throw Error("visual hull: the working volume is empty");
  }
  min_views_ = options.min_views > 0 ? options.min_views : (nc >= 3 ? nc - 1 : nc);
  if (min_views_ > nc) {
    throw Error("visual hull: min_views " + std::to_string(min_views_) + " exceeds the " +
                std::to_string(nc) + " cameras");
  }
  for (const Camera& cam : cameras_) {
    if (cam.width <= 0 || cam.height <= 0 || cam.width > 32000 || cam.height > 32000) {
      throw Error("visual hull: camera '" + cam.name + "' has no valid image size");
    }
  }
  // The volume shrinks to where enough cameras look (sampled every 10 cm, kept with a 10 cm
  // margin): a large room's corners would only cost table memory.
  Eigen::AlignedBox3d seen;
  const double probe = 0.1;
  const Eigen::Vector3d vmin = options.volume.min(), vmax = options.volume.max();
  for (double x = vmin.x(); x <= vmax.x(); x += probe) {
    for (double y = vmin.y(); y <= vmax.y(); y += probe) {
      for (double z = vmin.z(); z <= vmax.z(); z += probe) {
        const Eigen::Vector3d X(x, y, z);
        int views = 0;
        for (const Camera& cam : cameras_) views += cam.in_frustum(X) ? 1 : 0;
        if (views >= min_views_) seen.extend(X);
      }
    }
  }
  if (seen.isEmpty())
    throw Error("visual hull: no part of the working volume is seen by enough cameras");
  const Eigen::AlignedBox3d volume(seen.min().cwiseMax(vmin) - Eigen::Vector3d::Constant(probe),
                                   seen.max().cwiseMin(vmax) + Eigen::Vector3d::Constant(probe));
  const Eigen::AlignedBox3d box(volume.min().cwiseMax(vmin), volume.max().cwiseMin(vmax));
  grid_.voxel = options.voxel_m;
  const Eigen::Vector3d extent = box.sizes() / options.voxel_m;
  for (int a = 0; a < 3; ++a) {
    blocks_[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / kBlock - 1e-9)));
    grid_.dims[a] = blocks_[a] * kBlock;
  }
  grid_.origin = box.min() + Eigen::Vector3d::Constant(0.5 * options.voxel_m);
  const double voxels = static_cast<double>(grid_.dims.x()) * grid_.dims.y() * grid_.dims.z();
  if (voxels * nc * sizeof(std::uint32_t) > 2e9) {
    throw Error("visual hull: " + std::to_string(static_cast<long>(voxels)) +
                " voxels is too many for the projection tables; use a larger voxel size");
  }
  const int nblocks = blocks_.x() * blocks_.y() * blocks_.z();
  block_live_.assign(nblocks, 0);
  lut_.assign(nc, std::vector<std::uint32_t>(static_cast<size_t>(nblocks) * kBlockVoxels));
  boxes_.assign(nc, std::vector<PixelBox>(nblocks));

  tbb::parallel_for(tbb::blocked_range<int>(0, nblocks, 64), [&](const tbb::blocked_range<int>& r) {
    std::vector<std::uint32_t> pix(nc);
    for (int b = r.begin(); b != r.end(); ++b) {
      const int bx = b % blocks_.x();
      const int bz = (b / blocks_.x()) % blocks_.z();
      const int by = b / (blocks_.x() * blocks_.z());
      std::vector<PixelBox> box(nc, PixelBox{std::numeric_limits<std::int16_t>::max(),
                                             std::numeric_limits<std::int16_t>::max(), -1, -1});
      std::vector<bool> unseen_somewhere(nc, false);
      bool live = false;
      for (int k = 0; k < kBlockVoxels; ++k) {
        const Eigen::Vector3i v(bx * kBlock + k % kBlock, by * kBlock + k / (kBlock * kBlock),
                                bz * kBlock + (k / kBlock) % kBlock);
        const Eigen::Vector3d X = grid_.center(v);
        int views = 0;
        for (int c = 0; c < nc; ++c) {
          const Camera& cam = cameras_[c];
          const auto px = cam.project(X);
          const std::uint32_t unseen = static_cast<std::uint32_t>(cam.width * cam.height) + 1;
          pix[c] = unseen;
          if (!px) continue;
          const double u = std::floor(px->x() + 0.5), vv = std::floor(px->y() + 0.5);
          if (u < 0 || vv < 0 || u >= cam.width || vv >= cam.height) continue;
          pix[c] = static_cast<std::uint32_t>(vv) * cam.width + static_cast<std::uint32_t>(u);
          ++views;
        }
        const size_t slot = static_cast<size_t>(b) * kBlockVoxels + k;
        if (views < min_views_) {
          for (int c = 0; c < nc; ++c) {
            lut_[c][slot] = static_cast<std::uint32_t>(cameras_[c].width * cameras_[c].height);
          }
          continue;
        }
        live = true;
        for (int c = 0; c < nc; ++c) {
          lut_[c][slot] = pix[c];
          const std::uint32_t w = cameras_[c].width;
          if (pix[c] > w * cameras_[c].height) {
            unseen_somewhere[c] = true;
            continue;
          }
          const auto u = static_cast<std::int16_t>(pix[c] % w);
          const auto vv = static_cast<std::int16_t>(pix[c] / w);
          box[c].u0 = std::min(box[c].u0, u);
          box[c].v0 = std::min(box[c].v0, vv);
          box[c].u1 = std::max(box[c].u1, u);
          box[c].v1 = std::max(box[c].v1, vv);
        }
      }
      block_live_[b] = live ? 1 : 0;
      for (int c = 0; c < nc; ++c) {
        // A camera that misses part of the block cannot veto it as a whole.
        boxes_[c][b] = unseen_somewhere[c] || !live ? PixelBox{1, 0, 0, 0} : box[c];
      }
    }
  });

  // A group's box per camera is the union of its live blocks' (no veto when one has none).
  groups_ = (blocks_.array() + kGroup - 1) / kGroup;
  const int ngroups = groups_.prod();
  group_live_.assign(ngroups, 0);
  group_boxes_.assign(nc, std::vector<PixelBox>(ngroups, PixelBox{1, 0, 0, 0}));
  for (int b = 0; b < nblocks; ++b) {
    if (!block_live_[b]) continue;
    const int bx = b % blocks_.x(), bz = (b / blocks_.x()) % blocks_.z();
    const int by = b / (blocks_.x() * blocks_.z());
    const int g = (by / kGroup * groups_.z() + bz / kGroup) * groups_.x() + bx / kGroup;
    const bool first = !group_live_[g];
    group_live_[g] = 1;
    for (int c = 0; c < nc; ++c) {
      PixelBox& u = group_boxes_[c][g];
      const PixelBox& k = boxes_[c][b];
      if (first) {
        u = k;
      } else if (u.u0 <= u.u1) {
        u = k.u0 > k.u1 ? k
                        : PixelBox{std::min(u.u0, k.u0), std::min(u.v0, k.v0), std::max(u.u1, k.u1),
                                   std::max(u.v1, k.v1)};
      }
    }
  }
}

void VisualHull::carve(const std::vector<cv::Mat>& silhouettes, Occupancy& out) const {
  const int nc = static_cast<int>(cameras_.size());
  if (static_cast<int>(silhouettes.size()) != nc) {
    throw Error("visual hull: got " + std::to_string(silhouettes.size()) + " silhouettes for " +
                std::to_string(nc) + " cameras");
  }
  // Per camera: the mask as 0/255 bytes followed by two sentinels (0 at W·H for voxels with too
  // few views, 255 at W·H + 1 for voxels this camera does not see), so that a voxel's test is
  // the AND of one byte per camera; plus a summed-area table over the mask's bounding box.
  std::vector<std::vector<std::uint8_t>> bytes(nc);
  std::vector<cv::Rect> roi(nc);
  std::vector<cv::Mat> sums(nc);
  tbb::parallel_for(0, nc, [&](int c) {
    const Camera& cam = cameras_[c];
    const cv::Mat& s = silhouettes[c];
    if (s.type() != CV_8UC1 || s.cols != cam.width || s.rows != cam.height) {
      throw Error("visual hull: silhouette of camera '" + cam.name + "' must be 8-bit " +
                  std::to_string(cam.width) + "x" + std::to_string(cam.height) + ", got " +
                  std::to_string(s.cols) + "x" + std::to_string(s.rows));
    }
    const size_t n = static_cast<size_t>(cam.width) * cam.height;
    bytes[c].resize(n + 2);
    cv::Mat binary(cam.height, cam.width, CV_8UC1, bytes[c].data());
    cv::threshold(s, binary, 0, 255, cv::THRESH_BINARY);
    bytes[c][n] = 0;
    bytes[c][n + 1] = 255;
    roi[c] = mask_box(binary);
    if (!roi[c].empty()) cv::integral(binary(roi[c]), sums[c], CV_32S);
  });

  // Whether some pixel of every constraining camera's box is in its silhouette.
  auto passes = [&](const std::vector<std::vector<PixelBox>>& boxes, int i) {
    for (int c = 0; c < nc; ++c) {
      const PixelBox& box = boxes[c][i];
      if (box.u0 > box.u1) continue;
      const cv::Rect& q = roi[c];
      const int u0 = std::max<int>(box.u0, q.x) - q.x,
                u1 = std::min<int>(box.u1, q.x + q.width - 1) - q.x;
      const int v0 = std::max<int>(box.v0, q.y) - q.y,
                v1 = std::min<int>(box.v1, q.y + q.height - 1) - q.y;
      if (u0 > u1 || v0 > v1) return false;
      const cv::Mat& S = sums[c];
      const int inside = S.at<int>(v1 + 1, u1 + 1) - S.at<int>(v0, u1 + 1) - S.at<int>(v1 + 1, u0) +
                         S.at<int>(v0, u0);
      if (inside == 0) return false;
    }
    return true;
  };
  const int nblocks = blocks_.x() * blocks_.y() * blocks_.z();
  std::vector<std::uint64_t> bits(nblocks, 0);
  tbb::parallel_for(
      tbb::blocked_range<int>(0, groups_.prod(), 8), [&](const tbb::blocked_range<int>& r) {
        std::vector<const std::uint32_t*> lut(nc);
        for (int g = r.begin(); g != r.end(); ++g) {
          if (!group_live_[g] || !passes(group_boxes_, g)) continue;
          const int gx = g % groups_.x(), gz = (g / groups_.x()) % groups_.z();
          const int gy = g / (groups_.x() * groups_.z());
          for (int by = gy * kGroup; by < std::min((gy + 1) * kGroup, blocks_.y()); ++by) {
            for (int bz = gz * kGroup; bz < std::min((gz + 1) * kGroup, blocks_.z()); ++bz) {
              for (int bx = gx * kGroup; bx < std::min((gx + 1) * kGroup, blocks_.x()); ++bx) {
                const int b = (by * blocks_.z() + bz) * blocks_.x() + bx;
                if (!block_live_[b] || !passes(boxes_, b)) continue;
                for (int c = 0; c < nc; ++c)
                  lut[c] = lut_[c].data() + static_cast<size_t>(b) * kBlockVoxels;
                std::uint64_t m = 0;
                for (int k = 0; k < kBlockVoxels; ++k) {
                  std::uint8_t v = 255;
                  for (int c = 0; c < nc; ++c) v &= bytes[c][lut[c][k]];
                  if (v) m |= std::uint64_t{1} << k;
                }
                bits[b] = m;
              }
            }
          }
        }
      });

  auto voxel_of = [&](int b, int k) {
    const int bx = b % blocks_.x();
    const int bz = (b / blocks_.x()) % blocks_.z();
    const int by = b / (blocks_.x() * blocks_.z());
    return Eigen::Vector3i(bx * kBlock + k % kBlock, by * kBlock + k / (kBlock * kBlock),
                           bz * kBlock + (k / kBlock) % kBlock);
  };
  Eigen::Vector3i lo = grid_.dims, hi = Eigen::Vector3i::Constant(-1);
  int count = 0;
  for (int b = 0; b < nblocks; ++b) {
    for (std::uint64_t m = bits[b]; m; m &= m - 1) {
      const Eigen::Vector3i v = voxel_of(b, __builtin_ctzll(m));
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
      ++count;
    }
  }
  out.grid = grid_;
  out.count = count;
  if (count == 0) {
    out.lo.setZero();
    out.size.setZero();
    out.cells.clear();
    return;
  }
  out.lo = lo;
  out.size = hi - lo + Eigen::Vector3i::Ones();
  out.cells.assign(static_cast<size_t>(out.size.prod()), 0);
  for (int b = 0; b < nblocks; ++b) {
    for (std::uint64_t m = bits[b]; m; m &= m - 1) {
      const Eigen::Vector3i r = voxel_of(b, __builtin_ctzll(m)) - lo;
      out.cells[(static_cast<size_t>(r.y()) * out.size.z() + r.z()) * out.size.x() + r.x()] = 1;
    }
  }
}

}  // namespace simcap::tracker
