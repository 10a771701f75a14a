#include "bench/rays_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "bench/bench_measures.h"
#include "bench/peers.h"
#include "core/parallel.h"
#include "sensors/echo.h"
#include "sensors/noise.h"
#include "sensors/sensor_model.h"

namespace proxsim::bench {

namespace {

using nlohmann::json;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// proxsim's pipeline as the simulation runs it: one batched Cast, then per
/// ray the echo and the sensor model (laser preset), with the keyed draws
/// made only when the echo counts (sim/SensorReader does the same, through
/// the same functions).
struct Pipeline {
  const RayCaster* caster = nullptr;
  SensorSpec spec = SensorSpec::Preset(SensorType::kLaser);
  std::vector<Hit> hits;
  std::vector<Reading> readings;

  std::unique_ptr<ParallelRunner> runner;

  void Run(std::span<const Ray> rays, int threads) {
    if (!runner || runner->threads() != threads) runner = std::make_unique<ParallelRunner>(threads);
    hits.resize(rays.size());
    readings.resize(rays.size());
    caster->Cast(rays, hits);
    runner->For(rays.size(), 4096, [&](std::size_t begin, std::size_t end) { Measure(rays, begin, end); });
  }

  void Measure(std::span<const Ray> rays, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Hit& hit = hits[i];
      const Echo echo = hit.is_hit() ? EchoOfHit(hit.distance_m, rays[i].direction_W.cast<double>(),
                                                 hit.normal_W.cast<double>())
                                     : Echo{};
      // (seed, sensor = beam of 32 rays, sample 0, ray in beam), as the simulation keys it
      readings[i] = proxsim::Measure(spec, echo, [this, i](int) {
        return KeyedNoiseDraw(spec.noise, {7, static_cast<std::uint32_t>(i / 32), 0, static_cast<std::uint32_t>(i % 32)});
      });
    }
  }
};

/// Hit/miss mismatches, the largest distance difference where both hit, and
/// how many rays differ by more than 1 mm (a ray that slipped through an edge
/// to a surface behind, rather than float rounding).
json Agreement(std::span<const float> a, std::span<const float> b) {
  std::size_t mismatches = 0, both = 0, over_1mm = 0;
  double max_diff = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const bool ha = std::isfinite(a[i]), hb = std::isfinite(b[i]);
    if (ha != hb) {
      ++mismatches;
    } else if (ha) {
      ++both;
      const double diff = std::abs(a[i] - b[i]);
      max_diff = std::max(max_diff, diff);
      if (diff > 1e-3) ++over_1mm;
    }
  }
  return {{"rays", std::min(a.size(), b.size())}, {"both_hit", both}, {"hit_miss_mismatches", mismatches},
          {"max_distance_diff_m", max_diff}, {"distance_diff_over_1mm", over_1mm}};
}

std::string SizeLabel(std::size_t target) {
  return target >= 1000000 ? std::to_string(target / 1000000) + "m" : std::to_string(target / 1000) + "k";
}

/// The engines of one scene size, built on the same triangles.
struct Engines {
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<EmbreePeer> embree;
  std::unique_ptr<RayPeer> bullet;
  std::unique_ptr<RayPeer> mujoco;
};

/// Builds every engine on `scene`; their build times and memory into `size`.
void BuildEngines(const BenchScene& scene, Engines& engines, json& size) {
  // proxsim: the scene's objects as one static world body, as Simulation builds it
  double rss = RssBytes();
  const auto start = Clock::now();
  engines.caster = std::make_unique<RayCaster>();
  {
    std::vector<BodyShape> shapes;
    const Scene as_scene = ToScene(scene);
    for (std::size_t id = 0; id < as_scene.objects.size(); ++id) {
      shapes.push_back({as_scene.objects[id].shape, as_scene.objects[id].X_WO, static_cast<std::int32_t>(id)});
    }
    engines.caster->AddBody(std::move(shapes), BodyKind::kWorld);
    engines.caster->Commit();
  }
  size["proxsim_build_s"] = Since(start);
  size["proxsim_bytes_rss"] = RssBytes() - rss;

  rss = RssBytes();
  engines.embree = std::make_unique<EmbreePeer>(scene, /*robust=*/false);
  size["embree_build_s"] = engines.embree->build_s();
  size["embree_bytes"] = engines.embree->bytes();
  size["embree_bytes_rss"] = RssBytes() - rss;

  std::string why_bullet, why_mujoco;
  rss = RssBytes();
  engines.bullet = MakeBulletPeer(scene, &why_bullet);
  size["bullet_bytes_rss"] = RssBytes() - rss;
  if (engines.bullet) size["bullet_build_s"] = engines.bullet->build_s();
  else size["bullet_unavailable"] = why_bullet;
  Progress("  built: proxsim %.3f s, Embree %.3f s (%.1f MB), Bullet %s s", size["proxsim_build_s"].get<double>(),
           engines.embree->build_s(), engines.embree->bytes() / 1e6,
           engines.bullet ? std::to_string(engines.bullet->build_s()).c_str() : "n/a");
  rss = RssBytes();
  engines.mujoco = MakeMujocoPeer(scene, &why_mujoco);
  size["mujoco_bytes_rss"] = RssBytes() - rss;
  if (engines.mujoco) {
    size["mujoco_build_s"] = engines.mujoco->build_s();
    size["mujoco_bytes"] = engines.mujoco->bytes();
    Progress("  built: MuJoCo %.2f s", engines.mujoco->build_s());
  } else {
    size["mujoco_unavailable"] = why_mujoco;
    Progress("  MuJoCo unavailable: %s", why_mujoco.c_str());
  }
}

/// The rays/s of every engine on one ray set, at 1 and 2 threads.
json RaceOnRays(const char* set_name, std::span<const Ray> rays, Pipeline& pipeline, RayCaster& caster,
                EmbreePeer& embree, RayPeer* bullet, std::size_t bullet_rays, RayPeer* mujoco,
                std::size_t mujoco_rays, int repeats, std::vector<float>* proxsim_distances,
                std::vector<float>* embree_distances, std::vector<float>* bullet_distances,
                std::vector<float>* mujoco_distances) {
  json out = {{"rays", rays.size()}};
  std::vector<float> distances(rays.size());
  bool identical = true;
  std::vector<Hit> hits_1t;
  std::vector<Reading> readings_1t;
  for (int threads : {1, 2}) {
    const std::string t = std::to_string(threads) + "t";
    caster.set_threads(threads);
    out["proxsim_rays_per_s_" + t] = RaysPerSecond(rays.size(), repeats, [&] { pipeline.Run(rays, threads); });
    // where the pipeline's time goes: RayCaster::Cast alone, and the model (echo, noise, Measure) alone
    {
      std::vector<Hit> hits(rays.size());
      out["proxsim_cast_only_rays_per_s_" + t] = RaysPerSecond(rays.size(), repeats, [&] { caster.Cast(rays, hits); });
    }
    // the same answers whatever the thread count
    if (threads == 1) {
      hits_1t = pipeline.hits;
      readings_1t = pipeline.readings;
    } else {
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit& a = hits_1t[i];
        const Hit& b = pipeline.hits[i];
        const Reading& ra = readings_1t[i];
        const Reading& rb = pipeline.readings[i];
        if (std::memcmp(&a.distance_m, &b.distance_m, sizeof(float)) != 0 || a.object_id != b.object_id ||
            a.normal_W != b.normal_W || ra.status != rb.status ||
            std::memcmp(&ra.d_m, &rb.d_m, sizeof(double)) != 0) {
          identical = false;
        }
      }
    }
    Progress("  %s %zu rays, %d thread%s: proxsim %.2f M rays/s", set_name, rays.size(), threads,
             threads > 1 ? "s" : "", out["proxsim_rays_per_s_" + t].get<double>() / 1e6);

    // bare Embree, every way of calling it; the best is the ceiling
    double best = 0;
    std::string best_call;
    for (EmbreeCall call : {EmbreeCall::kSingle, EmbreeCall::kPacket4, EmbreeCall::kPacket8, EmbreeCall::kPacket16,
                            EmbreeCall::kStream}) {
      embree.set_call(call);
      const double rps = RaysPerSecond(rays.size(), repeats, [&] { embree.Cast(rays, distances, threads); });
      out["embree_rays_per_s_" + t][EmbreeCallName(call)] = rps;
      if (rps > best) {
        best = rps;
        best_call = EmbreeCallName(call);
      }
      if (call == EmbreeCall::kSingle && threads == 1 && embree_distances) *embree_distances = distances;
    }
    out["embree_best_rays_per_s_" + t] = best;
    out["embree_best_call_" + t] = best_call;
    Progress("  %s bare Embree best %.2f M rays/s (%s)", set_name, best / 1e6, best_call.c_str());

    // the slow peers on a fixed prefix of the same rays
    const auto time_slow_peer = [&](const char* key, const char* name, RayPeer* peer, std::size_t count,
                                    std::vector<float>* distances_1t) {
      if (!peer) return;
      std::vector<float> d(count);
      const auto subset = rays.first(count);
      const double rays_per_s = RaysPerSecond(count, 1, [&] { peer->Cast(subset, d, threads); });
      out[std::string(key) + "_rays_per_s_" + t] = rays_per_s;
      if (threads == 1 && distances_1t) *distances_1t = d;
      Progress("  %s %s %.4f M rays/s on %zu rays", set_name, name, rays_per_s / 1e6, count);
    };
    time_slow_peer("bullet", "Bullet", bullet, bullet_rays, bullet_distances);
    time_slow_peer("mujoco", "MuJoCo", mujoco, mujoco_rays, mujoco_distances);
  }
  out["proxsim_bit_identical_1t_2t"] = identical;
  if (proxsim_distances) {
    proxsim_distances->resize(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
      (*proxsim_distances)[i] = hits_1t[i].is_hit() ? hits_1t[i].distance_m : kInfinity;
    }
  }
  out["bullet_rays"] = bullet ? bullet_rays : 0;
  out["mujoco_rays"] = mujoco ? mujoco_rays : 0;
  return out;
}

/// The engines raced on both ray sets of one scene size, their answers
/// compared, and the ratios the targets are stated in; into `size`.
void RaceEngines(const BenchScene& scene, std::size_t target, bool quick, std::span<const Ray> incoherent,
                 std::span<const Ray> fans, int repeats, Engines& engines, json& size) {
  // the slow peers get a fixed prefix of the rays, sized to take about a second
  const std::size_t ray_count = incoherent.size();
  const std::size_t bullet_rays = std::min(ray_count, target >= 1'000'000 ? std::size_t{200'000} : std::size_t{500'000});
  const std::size_t mujoco_rays = quick ? (target >= 1'000'000 ? 100 : target >= 100'000 ? 500 : 2000)
                                        : (target >= 1'000'000 ? 300 : target >= 100'000 ? 2000 : 10000);
  RayCaster& caster = *engines.caster;
  RayPeer* bullet = engines.bullet.get();
  RayPeer* mujoco = engines.mujoco.get();
  Pipeline pipeline;
  pipeline.caster = &caster;
  std::vector<float> d_proxsim, d_embree, d_bullet, d_mujoco;
  size["incoherent"] = RaceOnRays("incoherent", incoherent, pipeline, caster, *engines.embree, bullet, bullet_rays,
                                  mujoco, mujoco_rays, repeats, &d_proxsim, &d_embree, &d_bullet, &d_mujoco);
  size["fans"] = RaceOnRays("fans", fans, pipeline, caster, *engines.embree, bullet, bullet_rays, mujoco, mujoco_rays,
                            repeats, nullptr, nullptr, nullptr, nullptr);

  // Embree with proxsim's scene flag (robust), to separate its cost from the pipeline's
  std::vector<float> d_embree_robust(incoherent.size());
  {
    EmbreePeer robust(scene, /*robust=*/true);
    for (int threads : {1, 2}) {
      size["embree_robust_rays_per_s_" + std::to_string(threads) + "t"] =
          RaysPerSecond(incoherent.size(), repeats, [&] { robust.Cast(incoherent, d_embree_robust, threads); });
    }
  }

  // the answers compared, ray by ray (incoherent set; proxsim at 1 thread as the reference)
  size["agreement"] = {{"embree", Agreement(d_proxsim, d_embree)},
                       {"embree_robust", Agreement(d_proxsim, d_embree_robust)}};
  if (bullet) size["agreement"]["bullet"] = Agreement(d_proxsim, d_bullet);
  if (mujoco) size["agreement"]["mujoco"] = Agreement(d_proxsim, d_mujoco);

  // the ratios the targets are stated in: proxsim's pipeline over each peer, incoherent rays
  const json& inc = size["incoherent"];
  for (const char* t : {"1t", "2t"}) {
    const double p = inc[std::string("proxsim_rays_per_s_") + t];
    size[std::string("ratio_vs_embree_") + t] = p / inc[std::string("embree_best_rays_per_s_") + t].get<double>();
    size[std::string("ratio_vs_embree_single_") + t] =
        p / inc[std::string("embree_rays_per_s_") + t]["rtcIntersect1"].get<double>();
    if (bullet) size[std::string("ratio_vs_bullet_") + t] = p / inc[std::string("bullet_rays_per_s_") + t].get<double>();
    if (mujoco) size[std::string("ratio_vs_mujoco_") + t] = p / inc[std::string("mujoco_rays_per_s_") + t].get<double>();
  }
  const json& fan = size["fans"];
  size["fans_ratio_vs_embree_2t"] = fan["proxsim_rays_per_s_2t"].get<double>() / fan["embree_best_rays_per_s_2t"].get<double>();
  size["thread_scaling"] = inc["proxsim_rays_per_s_2t"].get<double>() / inc["proxsim_rays_per_s_1t"].get<double>();
}

}  // namespace

json RaysSection(bool quick, std::size_t rays_per_set, int repeats, BenchScene* scene_1m) {
  json section;
  const auto incoherent = IncoherentRays(rays_per_set, 1);
  const auto fans = FanRays(rays_per_set, 32, 2);
  for (std::size_t target : {std::size_t{10'000}, std::size_t{100'000}, std::size_t{1'000'000}}) {
    const std::string label = SizeLabel(target);
    const auto start = Clock::now();
    BenchScene scene = MakeBenchDiningRoom(target);
    json size = {{"triangles", scene.triangle_count},
                 {"objects", scene.objects.size()},
                 {"cell_m", scene.cell_m},
                 {"generate_s", Since(start)}};
    Progress("scene %s: %zu triangles in %zu objects (generated in %.2f s)", label.c_str(), scene.triangle_count,
             scene.objects.size(), size["generate_s"].get<double>());
    Engines engines;
    BuildEngines(scene, engines, size);
    RaceEngines(scene, target, quick, incoherent, fans, repeats, engines, size);
    section["scenes"][label] = size;
    if (target >= 1'000'000 && scene_1m) *scene_1m = std::move(scene);
  }

  // the headline figures (at 2 threads: the whole machine)
  const json& s = section["scenes"];
  section["ratio_vs_embree_10k"] = s["10k"]["ratio_vs_embree_2t"];
  section["ratio_vs_embree_100k"] = s["100k"]["ratio_vs_embree_2t"];
  section["ratio_vs_embree_1m"] = s["1m"]["ratio_vs_embree_2t"];
  section["ratio_vs_bullet_100k"] = s["100k"].value("ratio_vs_bullet_2t", json(nullptr));
  section["ratio_vs_mujoco_100k"] = s["100k"].value("ratio_vs_mujoco_2t", json(nullptr));
  section["thread_scaling"] = s["100k"]["thread_scaling"];
  section["thread_scaling_1m"] = s["1m"]["thread_scaling"];
  return section;
}

std::string RaysReport(const json& r) {
  std::ostringstream out;
  char line[512];
  const auto M = [](const json& v) { return v.is_number() ? v.get<double>() / 1e6 : std::nan(""); };
  out << "| scene | rays | threads | proxsim pipeline | bare Embree best (call) | Embree robust | Bullet | MuJoCo | "
         "proxsim/Embree | proxsim/Bullet | proxsim/MuJoCo |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string label : {"10k", "100k", "1m"}) {
    if (!r.at("scenes").contains(label)) continue;
    const json& s = r.at("scenes").at(label);
    for (const char* set : {"incoherent", "fans"}) {
      const json& x = s.at(set);
      for (const char* t : {"1t", "2t"}) {
        const std::string T = t;
        const double p = x.at("proxsim_rays_per_s_" + T);
        const double e = x.at("embree_best_rays_per_s_" + T);
        const double b = x.value("bullet_rays_per_s_" + T, std::nan(""));
        const double m = x.value("mujoco_rays_per_s_" + T, std::nan(""));
        const std::string robust =
            std::string(set) == "incoherent" ? std::to_string(M(s.at("embree_robust_rays_per_s_" + T))).substr(0, 5) : "";
        std::snprintf(line, sizeof line, "| %s (%zu tri) | %s | %c | %.2f M/s | %.2f M/s (%s) | %s | %.3f M/s | %.5f M/s | %.2f | %.1f | %.0f |\n",
                      label.c_str(), s.at("triangles").get<std::size_t>(), set, t[0], p / 1e6, e / 1e6,
                      x.at("embree_best_call_" + T).get<std::string>().c_str(), robust.c_str(), b / 1e6, m / 1e6, p / e,
                      p / b, p / m);
        out << line;
      }
    }
  }
  out << "\n| scene | build: proxsim | Embree | Bullet | MuJoCo (MJCF parse + compile) | Embree BVH bytes | proxsim RSS Δ | "
         "agreement vs Embree / Bullet / MuJoCo (mismatches of rays, max |Δd|) |\n|---|---|---|---|---|---|---|---|\n";
  for (const std::string label : {"10k", "100k", "1m"}) {
    if (!r.at("scenes").contains(label)) continue;
    const json& s = r.at("scenes").at(label);
    std::string agree;
    for (const char* peer : {"embree", "bullet", "mujoco"}) {
      if (!s.at("agreement").contains(peer)) continue;
      const json& a = s.at("agreement").at(peer);
      char buf[128];
      std::snprintf(buf, sizeof buf, "%s%zu/%zu, %.1e m", agree.empty() ? "" : "; ", a.at("hit_miss_mismatches").get<std::size_t>(),
                    a.at("rays").get<std::size_t>(), a.at("max_distance_diff_m").get<double>());
      agree += buf;
    }
    std::snprintf(line, sizeof line, "| %s | %.3f s | %.3f s | %.3f s | %.2f s | %.1f MB | %.1f MB | %s |\n", label.c_str(),
                  s.at("proxsim_build_s").get<double>(), s.at("embree_build_s").get<double>(), s.value("bullet_build_s", std::nan("")),
                  s.value("mujoco_build_s", std::nan("")), s.at("embree_bytes").get<double>() / 1e6,
                  s.at("proxsim_bytes_rss").get<double>() / 1e6, agree.c_str());
    out << line;
  }
  return out.str();
}

}  // namespace proxsim::bench
