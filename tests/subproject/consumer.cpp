// SPDX-License-Identifier: MIT
// The smallest user of the engine as a subproject: a world of a thousand entities, queried.
#include <cstdio>

#include "ecs/query.h"
#include "ecs/world.h"

struct Mass {
  float kilograms = 0.0f;
};

int main() {
  sg::ecs::World world;
  for (int i = 0; i < 1000; ++i) world.add<Mass>(world.create(), float(i));
  double total = 0.0;
  world.query<const Mass>().for_each([&](sg::ecs::Entity, const Mass& mass) { total += mass.kilograms; });
  std::printf("%.0f\n", total);
  return total == 499500.0 ? 0 : 1;
}
