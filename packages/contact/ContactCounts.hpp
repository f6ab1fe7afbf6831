#pragma once
// How many slave nodes are in which contact state (history output), a light header for the output and
// model layers.
namespace contessa::contact {

struct ContactCounts {
  int active = 0, newlyActive = 0, stick = 0, slip = 0;
};

}  // namespace contessa::contact
