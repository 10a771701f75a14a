#include "output/scene_json.h"

#include <cctype>
#include <charconv>
#include <string_view>
#include <cstdlib>

namespace proxsim {

namespace {

// A float vertex coordinate as the double of its shortest decimal form, so
// that the JSON holds "0.0123457" and not the float's 17-digit double
// expansion: half the size for a robot of meshes, and still exactly the
// float the ray caster uses.
double ShortestDecimal(float value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text - 1, value);
  if (error != std::errc()) return value;
  *end = '\0';
  return std::strtod(text, nullptr);
}
template <typename... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <typename... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;  // clang 14 has no aggregate deduction yet
}  // namespace

nlohmann::json ShapeToJson(const Shape& shape, const Pose& X) {
  nlohmann::json j;
  j["shape"] = ShapeKindName(shape);
  std::visit(Overloaded{
                 [&](const Box& box) { j["size_m"] = {box.size_m.x(), box.size_m.y(), box.size_m.z()}; },
                 [&](const Sphere& sphere) { j["radius_m"] = sphere.radius_m; },
                 [&](const Cylinder& cylinder) {
                   j["radius_m"] = cylinder.radius_m;
                   j["length_m"] = cylinder.length_m;
                 },
                 [&](const Plane&) {},
                 [&](const Mesh& mesh) {
                   nlohmann::json vertices = nlohmann::json::array();
                   for (const Vec3f& v : mesh.data->vertices_O)
                     vertices.push_back({ShortestDecimal(v.x()), ShortestDecimal(v.y()), ShortestDecimal(v.z())});
                   j["vertices_m"] = std::move(vertices);
                   j["triangles"] = mesh.data->triangles;
                   j["file"] = mesh.file;
                 },
             },
             shape);
  const Eigen::Quaterniond q(X.linear());
  j["xyz_m"] = {X.translation().x(), X.translation().y(), X.translation().z()};
  j["quat_wxyz"] = {q.w(), q.x(), q.y(), q.z()};
  return j;
}

nlohmann::json SceneToJson(const Scenario& scenario, const std::vector<LinkShapes>& robot_links) {
  nlohmann::json doc;
  doc["duration_s"] = scenario.duration_s;
  doc["rate_hz"] = scenario.rate_hz;
  nlohmann::json objects = nlohmann::json::array();
  for (std::size_t id = 0; id < scenario.scene.objects.size(); ++id) {
    const SceneObject& object = scenario.scene.objects[id];
    nlohmann::json j = ShapeToJson(object.shape, object.X_WO);
    j["id"] = id;
    j["name"] = object.name;
    j["albedo"] = object.material.albedo;
    j["specular"] = object.material.specular;
    objects.push_back(std::move(j));
  }
  doc["objects"] = std::move(objects);
  if (robot_links.empty()) {
    doc["robot"] = nullptr;
  } else {
    nlohmann::json links = nlohmann::json::array();
    for (const LinkShapes& link : robot_links) {
      nlohmann::json shapes = nlohmann::json::array();
      for (const BodyShape& shape : link.shapes) shapes.push_back(ShapeToJson(shape.shape, shape.X_BO));
      links.push_back({{"name", link.name}, {"shapes", std::move(shapes)}});
    }
    doc["robot"] = {{"links", std::move(links)}};
  }
  nlohmann::json sensors = nlohmann::json::array();
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    const SensorConfig& sensor = scenario.sensors[i];
    sensors.push_back({{"index", i},
                       {"name", sensor.name},
                       {"type", SensorTypeName(sensor.spec.type)},
                       {"link", sensor.link},
                       {"min_range_m", sensor.spec.min_range_m},
                       {"max_range_m", sensor.spec.max_range_m},
                       {"max_incidence_deg", sensor.spec.max_incidence_deg}});
  }
  doc["sensors"] = std::move(sensors);
  return doc;
}

std::string SceneJsonText(const Scenario& scenario, const std::vector<LinkShapes>& robot_links) {
  nlohmann::json doc = SceneToJson(scenario, robot_links);
  // each mesh list is swapped for a numbered placeholder string, the
  // document indented, then the placeholders replaced by the compact lists
  std::vector<std::string> compact;
  const auto swap_out = [&](nlohmann::json& shape) {
    for (const char* key : {"vertices_m", "triangles"}) {
      if (!shape.contains(key)) continue;
      compact.push_back(shape[key].dump());
      std::string placeholder(1, '\x01');
      placeholder += std::to_string(compact.size() - 1);
      placeholder += '\x01';
      shape[key] = placeholder;
    }
  };
  for (auto& object : doc["objects"]) swap_out(object);
  if (doc["robot"].is_object())
    for (auto& link : doc["robot"]["links"])
      for (auto& shape : link["shapes"]) swap_out(shape);
  const std::string indented = doc.dump(1);
  std::string text;
  text.reserve(indented.size() + 16);
  constexpr std::string_view kOpen = "\"\\u0001", kClose = "\\u0001\"";
  for (std::size_t i = 0; i < indented.size();) {
    const std::size_t at = indented.find(kOpen, i);
    if (at == std::string::npos) {
      text.append(indented, i, std::string::npos);
      break;
    }
    text.append(indented, i, at - i);
    // a placeholder is "\u0001N\u0001" with N a list's number; anything else is copied as it is
    std::size_t end = at + kOpen.size(), n = 0;
    while (end < indented.size() && std::isdigit(static_cast<unsigned char>(indented[end])) && end - at < 20)
      n = 10 * n + static_cast<std::size_t>(indented[end++] - '0');
    if (end > at + kOpen.size() && n < compact.size() && indented.compare(end, kClose.size(), kClose) == 0) {
      text += compact[n];
      i = end + kClose.size();
    } else {
      text += indented[at];
      i = at + 1;
    }
  }
  return text + "\n";
}

}  // namespace proxsim
