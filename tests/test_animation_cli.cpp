// stenciltess's animation mode: topology and plan made once from the rest
// mesh, every frame's output byte-identical to a run on that frame alone; a
// frame with other connectivity is named and nothing is written.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>

#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"

using namespace stencil_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

void write_obj(const Mesh& m, const fs::path& path) {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& p : m.positions) out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  std::size_t k = 0;
  for (int size : m.face_sizes) {
    out << "f";
    for (int c = 0; c < size; ++c) out << " " << m.face_vertices[k++] + 1;
    out << "\n";
  }
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Frames frame_<k>.obj of the mesh with its vertices moved randomly.
std::vector<fs::path> make_frames(const Mesh& rest, const fs::path& dir, int count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> offset(-0.05, 0.05);
  std::vector<fs::path> frames;
  for (int k = 0; k < count; ++k) {
    Mesh m = rest;
    for (auto& p : m.positions)
      for (double& x : p) x += offset(rng);
    frames.push_back(dir / ("frame_" + std::to_string(k) + ".obj"));
    write_obj(m, frames.back());
  }
  return frames;
}

void check_animation(const std::string& tables, const std::string& mesh_name, const std::string& rates) {
  const fs::path dir = scratch_dir("animation-" + mesh_name);
  const fs::path rest = kMeshes / (mesh_name + ".obj");
  const std::vector<fs::path> frames = make_frames(read_obj(rest.string()), dir, 3);
  fs::create_directories(dir / "out");
  const CliResult r = run_stenciltess("--tables " + tables + " --mesh " + rest.string() + " --frames '" +
                                      (dir / "frame_*.obj").string() + "' " + rates + " --out '" + (dir / "out" / "f%02d.ply").string() + "'");
  INFO(r.output);
  REQUIRE(r.status == 0);
  REQUIRE(r.output.find("frame 3/3") != std::string::npos);  // progress
  CHECK(r.output.find("3 frames of ") != std::string::npos);
  CHECK(r.output.find("f00.ply .. ") != std::string::npos);
  for (int k = 0; k < 3; ++k) {
    const fs::path single = dir / ("single_" + std::to_string(k) + ".ply");
    const CliResult s = run_stenciltess("--tables " + tables + " --mesh " + frames[static_cast<std::size_t>(k)].string() + " " + rates +
                                        " --out " + single.string());
    REQUIRE(s.status == 0);
    const fs::path animated = dir / "out" / ("f0" + std::to_string(k) + ".ply");
    REQUIRE(fs::exists(animated));
    INFO("frame " << k);
    REQUIRE(bytes_of(animated) == bytes_of(single));
  }
  fs::remove_all(dir);
}

}  // namespace

TEST_CASE("stenciltess --frames writes every frame as a single run on it would", "[runtime][tools][frames]") {
  const std::string nonpoly = generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").parent_path().string();
  const std::string loop = generated_table("loop", "--valence 3-8 --n 24", "sgt").parent_path().string();
  check_animation(nonpoly, "torus-3-5", "--rate 6");
  check_animation(loop, "tri-mix", "--rate 5");
}

TEST_CASE("stenciltess --frames with one frame says so in the singular", "[runtime][tools][frames]") {
  const std::string loop = generated_table("loop", "--valence 3-8 --n 24", "sgt").parent_path().string();
  const fs::path dir = scratch_dir("animation-one");
  const fs::path rest = kMeshes / "tri-mix.obj";
  make_frames(read_obj(rest.string()), dir, 1);
  const fs::path out = dir / "f00.ply";
  const CliResult r = run_stenciltess("--tables " + loop + " --mesh " + rest.string() + " --frames '" +
                                      (dir / "frame_*.obj").string() + "' --rate 2 --out '" + (dir / "f%02d.ply").string() + "'");
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("1 frame of ") != std::string::npos);
  CHECK(r.output.find("wrote " + out.string() + "\n") != std::string::npos);
  CHECK(fs::exists(out));
  fs::remove_all(dir);
}

TEST_CASE("stenciltess --frames refuses a frame with other connectivity, and writes nothing", "[runtime][tools][frames][errors]") {
  const std::string nonpoly = generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").parent_path().string();
  const fs::path dir = scratch_dir("animation-errors");
  const fs::path rest = kMeshes / "cube.obj";
  Mesh cube = read_obj(rest.string());
  make_frames(cube, dir, 2);
  std::swap(cube.face_vertices[0], cube.face_vertices[1]);  // another face order: other connectivity
  write_obj(cube, dir / "frame_2.obj");
  fs::create_directories(dir / "out");
  const std::string frames = " --frames '" + (dir / "frame_*.obj").string() + "'";
  CliResult r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + frames + " --rate 3 --out '" +
                                (dir / "out" / "f%d.obj").string() + "'");
  CHECK(r.status == 1);
  CHECK(r.output.find("frame_2.obj: frame 2 has another connectivity than") != std::string::npos);
  CHECK(fs::is_empty(dir / "out"));
  r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + frames + " --rate 3 --out " + (dir / "out" / "f.obj").string());
  CHECK(r.status == 1);
  CHECK(r.output.find("needs exactly one frame number such as %04d") != std::string::npos);
  r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + frames + " --rate 3 --out '" + (dir / "out" / "%s.obj").string() + "'");
  CHECK(r.status == 1);
  CHECK(r.output.find("only %d") != std::string::npos);
  r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + " --frames '" + (dir / "none_*.obj").string() +
                      "' --rate 3 --out '" + (dir / "out" / "f%d.obj").string() + "'");
  CHECK(r.status == 1);
  CHECK(r.output.find("names no file") != std::string::npos);
  CHECK(fs::is_empty(dir / "out"));
  fs::remove_all(dir);
}

TEST_CASE("stenciltess --frames keeps the files that were there when a frame fails, and never writes over a frame",
          "[runtime][tools][frames][errors]") {
  const std::string nonpoly = generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").parent_path().string();
  const fs::path dir = scratch_dir("animation-keep");
  const fs::path rest = kMeshes / "cube.obj";
  make_frames(read_obj(rest.string()), dir, 4);
  const std::string frames = " --frames '" + (dir / "frame_*.obj").string() + "'";
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "f0.ply") << "earlier 0";
  std::ofstream(dir / "out" / "f1.ply") << "earlier 1";
  fs::create_directories(dir / "out" / "f2.ply");  // frame 2 cannot be written: frames 0 and 1 must stay as they were
  CliResult r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + frames + " --rate 3 --out '" +
                                (dir / "out" / "f%d.ply").string() + "'");
  CHECK(r.status == 1);
  CHECK(r.output.find("f2.ply: is a directory") != std::string::npos);
  CHECK(bytes_of(dir / "out" / "f0.ply") == "earlier 0");
  CHECK(bytes_of(dir / "out" / "f1.ply") == "earlier 1");
  CHECK(!fs::exists(dir / "out" / "f3.ply"));
  std::size_t files = 0;  // nothing staged is left behind
  for (const auto& entry : fs::directory_iterator(dir / "out")) files += entry.is_regular_file() ? 1 : 0;
  CHECK(files == 2);

  // An output pattern that names the frames themselves (frame_2.obj would be
  // written before it is read): refused before anything is written.
  const std::string frame2 = bytes_of(dir / "frame_2.obj");
  r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + frames + " --rate 3 --out '" +
                      (dir / "frame_%d.obj").string() + "'");
  CHECK(r.status == 1);
  CHECK(r.output.find("frame_0.obj is an input and the output") != std::string::npos);
  CHECK(bytes_of(dir / "frame_2.obj") == frame2);

  fs::remove_all(dir / "out" / "f2.ply");  // now every frame is written, over the earlier files
  r = run_stenciltess("--tables " + nonpoly + " --mesh " + rest.string() + frames + " --rate 3 --out '" +
                      (dir / "out" / "f%d.ply").string() + "'");
  CHECK(r.status == 0);
  for (int k = 0; k < 4; ++k) CHECK(bytes_of(dir / "out" / ("f" + std::to_string(k) + ".ply")).rfind("ply\n", 0) == 0);
  files = 0;
  for (const auto& entry : fs::directory_iterator(dir / "out")) files += entry.is_regular_file() ? 1 : 0;
  CHECK(files == 4);
  fs::remove_all(dir);
}

TEST_CASE("stenciltess --frames: a frame without tags takes the mesh's, one with other tags is refused, not ignored",
          "[runtime][tools][frames][errors]") {
  // A frame's own `t hole` used to be ignored without a word: its output was
  // the mesh's surface, not the one its file asks for.
  const std::string nonpoly = generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").parent_path().string();
  const fs::path dir = scratch_dir("animation-tags");
  const std::string cube = bytes_of(kMeshes / "cube.obj");
  const std::string hole = "\nt hole 1/0/0 3\n";
  std::ofstream(dir / "rest.obj") << cube << hole;
  const std::vector<fs::path> frames = make_frames(read_obj((kMeshes / "cube.obj").string()), dir, 2);
  std::ofstream(frames[1], std::ios::app) << hole;  // frame 1 repeats the mesh's tag; frame 0 has none
  const std::string tess = "--tables " + nonpoly + " --rate 3 ";
  CliResult r = run_stenciltess(tess + "--mesh " + (dir / "rest.obj").string() + " --frames '" + (dir / "frame_*.obj").string() +
                                "' --out '" + (dir / "f%d.obj").string() + "'");
  INFO(r.output);
  REQUIRE(r.status == 0);
  // Each frame equals a run on the frame with the mesh's hole.
  for (int k = 0; k < 2; ++k) {
    const fs::path alone = dir / ("alone" + std::to_string(k) + ".obj");
    std::ofstream(alone) << bytes_of(frames[static_cast<std::size_t>(k)]) << (k == 0 ? hole : "");
    const fs::path out = dir / ("single" + std::to_string(k) + ".obj");
    REQUIRE(run_stenciltess(tess + "--mesh " + alone.string() + " --out " + out.string()).status == 0);
    CHECK(bytes_of(out) == bytes_of(dir / ("f" + std::to_string(k) + ".obj")));
  }
  // A frame with another hole: refused, naming it, and nothing written.
  fs::remove(dir / "f0.obj");
  fs::remove(dir / "f1.obj");
  std::ofstream(frames[1]) << bytes_of(frames[0]) << "\nt hole 1/0/0 4\n";
  r = run_stenciltess(tess + "--mesh " + (dir / "rest.obj").string() + " --frames '" + (dir / "frame_*.obj").string() +
                      "' --out '" + (dir / "f%d.obj").string() + "'");
  CHECK(r.status == 1);
  CHECK(r.output.find("frame_1.obj: frame 1 has other tag lines") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "f0.obj"));
  fs::remove_all(dir);
}
