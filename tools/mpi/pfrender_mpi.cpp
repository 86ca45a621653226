// pfrender-mpi: renders a scene over MPI ranks by sort-last compositing -- PixelFlow's image
// composition (Molnar et al. 1992, cited in seed 003 section 1): each rank draws its share of
// the scene's objects into a full frame with its own renderer threads (PF_NUM_THREADS or
// --threads), pfCompositeDepthMPI merges the frames by depth, and rank 0 writes the PNG.
//   mpirun -np 4 pfrender-mpi SCENE.json [-o OUT.png] [--size WxH] [--threads N] [--split S]
//          [--algorithm A] [--compress] [--timeout SECONDS] [--depth-out FILE.pfm] [--stats]
//   mpirun -np 4 pfrender-mpi --sphere-cloud N [--seed S] [--per-object K] [--radius-scale R] ...
//   pfrender-mpi --sphere-cloud N --write-scene FILE.json   (the same spheres as a scene file)
// --split: round-robin (default), block or spatial (tools/mpi/object_split.h).
// Exit status: 0 drawn and written; 1 a bad scene, a GL error, a compositing error (on every
// rank) or an unwritable output; 2 a bad command line.
#include <CLI/CLI.hpp>

#include <primflow/composite.h>
#include <primflow/gl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "model/model_file.h"
#include "mpi/object_split.h"
#include "mpi/sphere_cloud.h"
#include "png_image.h"
#include "scene/scene.h"

namespace {

int g_rank = 0, g_ranks = 1;

// Every rank's flag, OR-ed: any rank failing makes every rank stop together.
bool anyRank(bool mine) {
  int in = mine ? 1 : 0, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out != 0;
}

// "WxH" with each side in 1..8192, as pfrender.
bool parseSize(const std::string& text, int& w, int& h) {
  const size_t x = text.find('x');
  if (x == std::string::npos) return false;
  auto side = [](const std::string& digits, int& out) {
    if (digits.empty() || digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::stoi(digits);
    return out >= 1 && out <= 8192;
  };
  return side(text.substr(0, x), w) && side(text.substr(x + 1), h);
}

struct Options {
  std::string scene_path, out, size, split_name = "round-robin", algorithm_name = "auto", depth_out, write_scene;
  int threads = 0;
  bool compress = false, stats = false;
  double timeout = 60.0;
  uint64_t cloud = 0;
  pf::cloud::SphereCloud sphere_cloud;
};

int run(int argc, char** argv);

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_ranks);
  int status = 1;
  try {
    status = run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::cerr << "pfrender-mpi: rank " << g_rank << ": out of memory\n";
    MPI_Abort(MPI_COMM_WORLD, 1);  // the other ranks may be waiting in a collective
  }
  MPI_Finalize();
  return status;
}

namespace {

int run(int argc, char** argv) {
  CLI::App app{"pfrender-mpi: render a scene over MPI ranks, composited by depth (docs/api.md)"};
  Options o;
  app.add_option("scene", o.scene_path, "scene file (.json, docs/scenes.md)");
  app.add_option("--sphere-cloud", o.cloud, "instead of a scene: N sphere impostors made from --seed")
      ->check(CLI::Range(uint64_t{1}, uint64_t{10000000000}));
  app.add_option("--seed", o.sphere_cloud.seed, "the sphere cloud's seed");
  app.add_option("--per-object", o.sphere_cloud.per_object, "spheres per object of the cloud (one glBegin)")
      ->check(CLI::Range(1, 1 << 20));
  app.add_option("--radius-scale", o.sphere_cloud.radius_scale, "the cloud's radii times this")
      ->check(CLI::Range(0.001f, 1000.0f));
  app.add_option("--write-scene", o.write_scene, "write the sphere cloud as a scene file and stop");
  app.add_option("-o,--output", o.out, "output PNG file, written by rank 0 (default: the scene's name, or cloud.png)");
  app.add_option("--size", o.size, "image size WxH (each 1..8192; default: the scene's, or 1920x1080)");
  app.add_option("--threads", o.threads, "rasterizer threads per rank (0: PF_NUM_THREADS or all cores)")
      ->check(CLI::Range(0, 256));
  app.add_option("--split", o.split_name, "which objects a rank draws: round-robin, block or spatial");
  app.add_option("--algorithm", o.algorithm_name, "compositing: auto, binary-swap or direct-send");
  app.add_flag("--compress", o.compress, "run-length code the bands sent (cleared regions cost one run)");
  app.add_option("--timeout", o.timeout, "seconds every rank waits for the others when compositing (0: no limit)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--depth-out", o.depth_out, "also write the composited depth buffer (window depth, 1 = cleared) as PFM");
  app.add_flag("--stats", o.stats, "print each rank's share, draw time and compositing figures");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = e.get_exit_code();
    if (g_rank == 0) app.exit(e);  // one rank prints the message (or --help)
    return code == 0 ? 0 : 2;
  }
  auto fail2 = [&](const std::string& message) {
    if (g_rank == 0) std::cerr << "pfrender-mpi: " << message << "\n";
    return 2;
  };
  if (o.scene_path.empty() == (o.cloud == 0)) return fail2("give a scene file or --sphere-cloud N (one of them)");
  if (!o.write_scene.empty() && o.cloud == 0) return fail2("--write-scene needs --sphere-cloud");
  const auto split = pf::split::parseSplit(o.split_name);
  if (!split) return fail2("--split must be round-robin, block or spatial, not '" + o.split_name + "'");
  int algorithm = PF_COMPOSITE_AUTO;
  if (o.algorithm_name == "binary-swap") algorithm = PF_COMPOSITE_BINARY_SWAP;
  else if (o.algorithm_name == "direct-send") algorithm = PF_COMPOSITE_DIRECT_SEND;
  else if (o.algorithm_name != "auto")
    return fail2("--algorithm must be auto, binary-swap or direct-send, not '" + o.algorithm_name + "'");
  o.sphere_cloud.count = o.cloud;
  // Every rank lists its objects (and the spatial split sorts them all): keep that list small.
  if (o.cloud && pf::cloud::objectCount(o.sphere_cloud) > (uint64_t{1} << 26))
    return fail2("--sphere-cloud makes more than 2^26 objects: raise --per-object");

  // The scene, read by every rank (the same file gives the same verdict everywhere).
  std::optional<pf::scene::Scene> scene;
  std::string error;
  if (!o.scene_path.empty()) {
    try {
      scene = pf::scene::loadScene(o.scene_path);
    } catch (const pf::scene::SceneError& e) {
      error = e.what();
    }
  } else {
    scene = pf::cloud::cloudFrame(1920, 1080);
  }
  if (anyRank(!error.empty())) {
    if (g_rank == 0) std::cerr << (error.empty() ? "pfrender-mpi: another rank could not read the scene" : error) << "\n";
    return 1;
  }
  int w = scene->width, h = scene->height;
  if (!o.size.empty() && !parseSize(o.size, w, h))
    return fail2("--size must be WxH with each side in 1..8192, not '" + o.size + "'");
  if (!o.write_scene.empty()) {
    bool ok = true;
    if (g_rank == 0 && !(ok = pf::cloud::writeCloudScene(o.sphere_cloud, w, h, o.write_scene, &error)))
      std::cerr << "pfrender-mpi: " << error << "\n";
    return anyRank(!ok) ? 1 : 0;
  }
  if (o.out.empty()) o.out = o.cloud ? "cloud.png" : std::filesystem::path(o.scene_path).stem().string() + ".png";

  // This rank's share.
  const uint64_t objects = o.cloud ? pf::cloud::objectCount(o.sphere_cloud) : scene->objects.size();
  const std::vector<uint64_t> mine = pf::split::objectsOfRank(*split, objects, g_rank, g_ranks, [&](uint64_t i) {
    return o.cloud ? pf::cloud::objectCentre(o.sphere_cloud, i).x : pf::split::objectCentre(scene->objects[i]).x;
  });

  // Draw it into a whole frame.
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, o.threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * 4);
  bool bound = ctx && pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h);
  if (anyRank(!bound)) {
    std::cerr << "pfrender-mpi: rank " << g_rank << ": " << (bound ? "another rank" : "could not create a context")
              << " failed\n";
    pfDestroyContext(ctx);
    return 1;
  }
  const auto t0 = std::chrono::steady_clock::now();
  try {
    pf::scene::beginScene(*scene, w, h);
    for (uint64_t i : mine) {
      if (o.cloud) pf::cloud::drawCloudObject(o.sphere_cloud, i);
      else pf::scene::drawObject(*scene, scene->objects[i]);
    }
    pfglFinish();
  } catch (const pf::scene::SceneError& e) {
    error = e.what();
  }
  const double draw_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const GLenum gl_error = pfglGetError();
  if (error.empty() && gl_error != GL_NO_ERROR) error = "pfrender-mpi: a GL error while drawing";
  if (anyRank(!error.empty())) {
    if (!error.empty()) std::cerr << error << " (rank " << g_rank << ")\n";
    pfDestroyContext(ctx);
    return 1;
  }

  // Composite.
  PFcompositeOptions options;
  pfCompositeDefaultOptions(&options);
  options.algorithm = algorithm;
  options.compress = o.compress ? 1 : 0;
  options.timeout_seconds = o.timeout;
  PFcompositeStats st;
  const int rc = pfCompositeDepthMPI(MPI_COMM_WORLD, &options, &st);
  if (rc != PF_COMPOSITE_OK) {
    std::cerr << "pfrender-mpi: rank " << g_rank << ": compositing failed: " << pfCompositeErrorString(rc) << "\n";
    pfDestroyContext(ctx);
    return 1;
  }
  if (o.stats) {
    const double row[6] = {static_cast<double>(mine.size()), draw_ms, st.seconds * 1e3, st.merge_seconds * 1e3,
                           static_cast<double>(st.bytes_sent), static_cast<double>(st.bytes_received)};
    std::vector<double> all(6 * static_cast<size_t>(g_ranks));
    MPI_Gather(row, 6, MPI_DOUBLE, all.data(), 6, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (g_rank == 0) {
      std::printf("%d ranks, %dx%d, %s, %s split, %s\n", g_ranks, w, h,
                  st.algorithm == PF_COMPOSITE_BINARY_SWAP ? "binary-swap" : "direct-send", o.split_name.c_str(),
                  o.compress ? "compressed" : "uncompressed");
      std::printf("rank  objects   draw ms  composite ms  merge ms   bytes sent  bytes received\n");
      for (int r = 0; r < g_ranks; ++r) {
        const double* v = &all[6 * static_cast<size_t>(r)];
        std::printf("%4d %8.0f %9.1f %13.1f %9.1f %12.0f %15.0f\n", r, v[0], v[1], v[2], v[3], v[4], v[5]);
      }
    }
  }
  int status = 0;
  if (g_rank == 0) {
    if (!pf::writePngBottomUp(o.out, pixels.data(), w, h, &error)) {
      std::cerr << "pfrender-mpi: " << error << "\n";
      status = 1;
    }
    GLint dw = 0, dh = 0, bytes = 0;
    void* depth = nullptr;
    if (status == 0 && !o.depth_out.empty() &&
        (!pfGetDepthBuffer(ctx, &dw, &dh, &bytes, &depth) ||
         !pf::model::writePfm(o.depth_out, w, h,
                              std::vector<float>(static_cast<const float*>(depth),
                                                 static_cast<const float*>(depth) + static_cast<size_t>(w) * h),
                              &error))) {
      std::cerr << "pfrender-mpi: " << (error.empty() ? "no depth buffer" : error) << "\n";
      status = 1;
    }
  }
  pfDestroyContext(ctx);
  return anyRank(status != 0) ? 1 : 0;
}

}  // namespace
