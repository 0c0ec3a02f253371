#include "cli/WorldRenderCommand.hpp"

#include <cstdio>
#include <memory>
#include <string>

#include "cli/CommandSupport.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"
#include "dynamap/robotio/sim/WorldRender.hpp"

namespace dynamap::app {

namespace {

struct WorldRenderOptions {
  std::string world;
  std::string out;
  double pixels_per_metre = 40.0;
};

void RunWorldRender(const WorldRenderOptions& options) {
  const std::string command = "world render";
  auto world = robotio::sim::LoadWorld(options.world);
  if (!world) FailCommand(command, world.error().message);
  robotio::sim::WorldRenderConfig config;
  config.pixels_per_metre = options.pixels_per_metre;
  if (auto status = robotio::sim::RenderWorldPng(*world, options.out, config); !status) {
    FailCommand(command, status.error().message);
  }
  std::printf("wrote %s\n", options.out.c_str());
}

}  // namespace

void RegisterWorldCommand(CLI::App& app) {
  CLI::App* world = app.add_subcommand("world", "Inspect simulator world files");
  world->require_subcommand(1);
  auto options = std::make_shared<WorldRenderOptions>();
  CLI::App* render = world->add_subcommand(
      "render", "Draw a world file top-down (walls, doors, furniture, holes, steps, people "
                "paths, robot start and scripted path) as a PNG");
  render->add_option("file", options->world, "World file (YAML)")->required();
  render->add_option("--out", options->out, "PNG to write")->required();
  render->add_option("--pixels-per-metre", options->pixels_per_metre, "Picture scale")
      ->check(CLI::Range(5.0, 400.0));
  render->callback([options] { RunWorldRender(*options); });
}

}  // namespace dynamap::app
