// cig engines [--json]
#include "cli/engines_command.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

#include "cli/cli_common.hpp"
#include "registry/engine_registry.hpp"

namespace cig::cli {

void EnginesCommand::add_to(CLI::App& app) {
  sub = app.add_subcommand("engines",
                           "list the raster engines: what each models and draws, its --engine-opt settings "
                           "(values, defaults) and what it can drop");
  sub->add_flag("--json", json, "print the list as JSON (led by its provenance)");
}

namespace {

std::vector<std::string> draws(const EngineInfo& e) {
  std::vector<std::string> d;
  if (e.can.polygons) d.push_back("polygons");
  if (e.light_points) d.push_back("light points");
  if (e.can.polyhedra) d.push_back("convex polyhedra (\"polyhedron\": true objects)");
  if (e.can.pipelines) d.push_back("rendering pipelines (--pipelines)");
  return d;
}

const char* cause_name(DropKind::Cause c) { return c == DropKind::Cause::kMemoryFull ? "memory full" : "cannot draw"; }

std::string default_text(const EngineOptionSpec& s) { return s.default_value.empty() ? "unset" : s.default_value; }

std::string engine_text(const EngineInfo& e) {
  std::ostringstream t;
  t << e.name << " (" << (e.can.bit_accurate ? "bit-accurate" : "double") << "): " << e.models << "\n  draws: ";
  const std::vector<std::string> d = draws(e);
  for (std::size_t k = 0; k < d.size(); ++k) t << (k ? ", " : "") << d[k];
  t << "\n";
  if (*e.can.twin_of) t << "  twin of: " << e.can.twin_of << " (the same kernels on double arithmetic)\n";
  if (*e.can.hardware_model)
    t << "  hardware model: " << e.can.hardware_model << ", co-simulated against it by cig cosim\n";
  if (e.can.reference)
    t << "  the reference: --reference " << e.name << ", " << e.name << "-snap, " << e.name << "-snap-priority\n";
  if (e.can.reference) t << "  --snap: snap vertex positions to the formatter grid first (exact depth planes kept)\n";
  t << "  --engine-opt settings:" << (e.options.empty() ? " none" : "") << "\n";
  std::size_t width = 0;
  for (const EngineOptionSpec& s : e.options) width = std::max(width, s.key.size() + 1 + s.range().size());
  width = std::min<std::size_t>(width, 28);  // a long syntax does not push every line right
  for (const EngineOptionSpec& s : e.options) {
    const std::string key = s.key + "=" + s.range();
    t << "    " << key << std::string(width - std::min(width, key.size()), ' ') << "  default " << default_text(s);
    if (!s.shorthand.empty()) t << ", also " << s.shorthand;
    t << ": " << s.help << "\n";
  }
  if (e.drops.empty()) {
    t << "  drops: nothing (the report's \"dropped\" is empty)\n";
  } else {
    t << "  drops (counted in the report's \"dropped\", warned of on stderr):\n";
    for (const DropKind& k : e.drops) t << "    " << k.key << " (" << cause_name(k.cause) << "): " << k.what << "\n";
  }
  return t.str();
}

nlohmann::ordered_json engine_json(const EngineInfo& e) {
  nlohmann::ordered_json j;
  j["name"] = e.name;
  j["models"] = e.models;
  j["arithmetic"] = e.can.bit_accurate ? "bit-accurate" : "double";
  j["draws"] = {{"polygons", e.can.polygons},
                {"light_points", e.light_points},
                {"polyhedra", e.can.polyhedra},
                {"rendering_pipelines", e.can.pipelines}};
  j["snap"] = e.can.reference;
  j["reference"] = e.can.reference;
  j["formatter"] = e.can.formatter;
  j["twin_of"] = e.can.twin_of;
  j["hardware_model"] = e.can.hardware_model;
  j["options"] = nlohmann::ordered_json::array();
  for (const EngineOptionSpec& s : e.options) {
    nlohmann::ordered_json o = {{"key", s.key}, {"values", s.range()}, {"default", s.default_value}, {"help", s.help}};
    if (s.kind == EngineOptionSpec::Kind::kChoice) o["choices"] = s.choices;
    if (s.kind == EngineOptionSpec::Kind::kInteger) o["range"] = {s.min, s.max};
    if (s.kind == EngineOptionSpec::Kind::kReal) o["range"] = {{"above", s.min}, {"max", s.max}};
    if (!s.shorthand.empty()) o["shorthand"] = s.shorthand;
    j["options"].push_back(o);
  }
  j["dropped"] = nlohmann::ordered_json::array();
  for (const DropKind& k : e.drops)
    j["dropped"].push_back({{"key", k.key}, {"cause", cause_name(k.cause)}, {"what", k.what}});
  return j;
}

}  // namespace

int EnginesCommand::run() {
  if (json) {
    nlohmann::ordered_json r;
    r["command"] = "engines";
    r["engines"] = nlohmann::ordered_json::array();
    for (const EngineInfo& e : engine_infos()) r["engines"].push_back(engine_json(e));
    std::cout << report_text(r);
    return 0;
  }
  std::cout << "cig engines: " << engine_infos().size()
            << " raster engines (--engine NAME; settings --engine-opt KEY=VALUE, repeatable)\n";
  for (const EngineInfo& e : engine_infos()) std::cout << "\n" << engine_text(e);
  return 0;
}

}  // namespace cig::cli
