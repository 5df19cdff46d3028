// The objects of a world. An ObjectId is an index into the universe; ids
// are stable for the life of a scenario.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "world/domain.h"
#include "world/fact.h"

namespace apprentice {

// What an object is to the robot. Items are what it carries; receptacles
// hold items "in" them and may have a door; surfaces hold items "on" them.
enum class ObjectKind { kItem, kReceptacle, kSurface };

std::string_view to_string(ObjectKind kind);
std::optional<ObjectKind> parse_object_kind(std::string_view text);
// The PDDL type a scenario gives objects of each kind: "item",
// "receptacle-place", "surface-place". (The types are not called
// "receptacle" and "surface" because those name predicates, and PDDL
// tools warn when a type and a predicate share a name.)
std::string_view type_name(ObjectKind kind);
// How messages name a type: the kind's word ("receptacle", "surface") for
// the kinds' types, otherwise the type's own name.
std::string type_word(const Domain& domain, TypeId type);

struct ObjectInfo {
  std::string id;        // "ketchup1"
  std::string category;  // "ketchup"
  ObjectKind kind = ObjectKind::kItem;
  TypeId type = kRootType;  // its PDDL type
  // Words a person uses to tell look-alikes apart ("top", "blue", "left"),
  // lower-case; empty for most objects.
  std::vector<std::string> properties;
};

class Universe {
 public:
  // Adds an object; the id must be new (checked).
  ObjectId add(ObjectInfo info);

  std::size_t size() const { return objects_.size(); }
  const ObjectInfo& info(ObjectId id) const { return objects_.at(id); }
  const std::string& name(ObjectId id) const { return objects_.at(id).id; }
  std::optional<ObjectId> find(std::string_view id) const;
  // In id order; from indexes kept by add(), so O(1) to find.
  const std::vector<ObjectId>& with_category(std::string_view category) const;
  const std::vector<ObjectId>& of_kind(ObjectKind kind) const;
  // The objects whose type is exactly `type` (not a subtype), in id order.
  const std::vector<ObjectId>& of_type(TypeId type) const;
  const std::vector<ObjectInfo>& objects() const { return objects_; }

 private:
  std::vector<ObjectInfo> objects_;
  std::unordered_map<std::string, ObjectId> by_id_;
  std::unordered_map<std::string, std::vector<ObjectId>> by_category_;
  std::array<std::vector<ObjectId>, 3> by_kind_;  // by ObjectKind
  std::vector<std::vector<ObjectId>> by_type_;    // by TypeId
};

}  // namespace apprentice
