#include "io/scene_json.h"

namespace proxsim {

namespace {
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
                   for (const Vec3f& v : mesh.data->vertices_O) vertices.push_back({v.x(), v.y(), v.z()});
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

nlohmann::json SceneToJson(const Scenario& scenario, const std::vector<LinkGeometryJson>& robot_links) {
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
    for (const LinkGeometryJson& link : robot_links) {
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

}  // namespace proxsim
