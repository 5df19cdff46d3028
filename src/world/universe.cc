#include "world/universe.h"

#include "util/check.h"

namespace apprentice {

std::string_view to_string(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kItem: return "object";
    case ObjectKind::kReceptacle: return "receptacle";
    case ObjectKind::kSurface: return "surface";
  }
  return "object";
}

std::optional<ObjectKind> parse_object_kind(std::string_view text) {
  if (text == "object" || text == "item") return ObjectKind::kItem;
  if (text == "receptacle") return ObjectKind::kReceptacle;
  if (text == "surface") return ObjectKind::kSurface;
  return std::nullopt;
}

std::string_view type_name(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::kItem: return "item";
    case ObjectKind::kReceptacle: return "receptacle-place";
    case ObjectKind::kSurface: return "surface-place";
  }
  return "item";
}

std::string type_word(const Domain& domain, TypeId type) {
  for (ObjectKind kind : {ObjectKind::kReceptacle, ObjectKind::kSurface})
    if (domain.types[type].name == type_name(kind)) return std::string(to_string(kind));
  return domain.types[type].name;
}

ObjectId Universe::add(ObjectInfo info) {
  auto id = static_cast<ObjectId>(objects_.size());
  auto [it, inserted] = by_id_.emplace(info.id, id);
  APPRENTICE_CHECK_MSG(inserted, "duplicate object id");
  by_category_[info.category].push_back(id);
  by_kind_.at(static_cast<std::size_t>(info.kind)).push_back(id);
  if (by_type_.size() <= info.type) by_type_.resize(static_cast<std::size_t>(info.type) + 1);
  by_type_[info.type].push_back(id);
  objects_.push_back(std::move(info));
  return id;
}

std::optional<ObjectId> Universe::find(std::string_view id) const {
  auto it = by_id_.find(std::string(id));
  if (it == by_id_.end()) return std::nullopt;
  return it->second;
}

const std::vector<ObjectId>& Universe::with_category(std::string_view category) const {
  static const std::vector<ObjectId> kNone;
  auto it = by_category_.find(std::string(category));
  return it == by_category_.end() ? kNone : it->second;
}

const std::vector<ObjectId>& Universe::of_kind(ObjectKind kind) const {
  return by_kind_.at(static_cast<std::size_t>(kind));
}

const std::vector<ObjectId>& Universe::of_type(TypeId type) const {
  static const std::vector<ObjectId> kNone;
  return type < by_type_.size() ? by_type_[type] : kNone;
}

}  // namespace apprentice
