// D* Lite (Koenig & Likhachev 2002, the optimised version of fig. 4): searches backward
// from the goal and repairs its result when cells change or the robot moves, using the key
// modifier km instead of reordering the queue (thesis 6.3).
#pragma once

#include <vector>

#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

class DStarLite {
 public:
  // Keeps its own copy of the grid; nothing is searched until Plan().
  DStarLite(TraversalGrid grid, GridIndex start, GridIndex goal);

  // Brings the search up to date (incrementally after the calls below) and returns the
  // path from the current start; `expansions` counts this call only.
  [[nodiscard]] GridPath Plan();

  // The robot is now at `start` (any cell; the queue keys stay valid through km).
  void MoveStart(GridIndex start);
  // Cells took new penalties; only the vertices whose edges changed are touched.
  void UpdateCells(const std::vector<CellChange>& changes);
  // A new goal restarts the search (all previous work refers to the old goal).
  void SetGoal(GridIndex goal);

  [[nodiscard]] const TraversalGrid& grid() const { return grid_; }
  [[nodiscard]] GridIndex start() const { return start_; }
  [[nodiscard]] GridIndex goal() const { return goal_; }

 private:
  struct Key {
    double k1;
    double k2;
    friend bool operator<(const Key& a, const Key& b) {
      return a.k1 < b.k1 || (a.k1 == b.k1 && a.k2 < b.k2);
    }
  };

  void Reset();
  [[nodiscard]] Key CalculateKey(int s) const;
  [[nodiscard]] double Heuristic(int s) const;
  [[nodiscard]] double BestSuccessorRhs(int s) const;
  void UpdateVertex(int s);
  void ComputeShortestPath();

  // Indexed binary min-heap over cell indices (D* Lite needs update and remove).
  void HeapPush(int s, Key key);
  void HeapRemove(int s);
  void HeapUpdate(int s, Key key);
  void SiftUp(int pos);
  void SiftDown(int pos);
  [[nodiscard]] bool HeapLess(int a, int b) const { return key_[heap_[a]] < key_[heap_[b]]; }

  TraversalGrid grid_;
  GridIndex start_;
  GridIndex goal_;
  GridIndex last_start_;
  double km_ = 0.0;
  std::vector<double> g_;
  std::vector<double> rhs_;
  std::vector<Key> key_;
  std::vector<int> heap_pos_;  // -1 when not queued.
  std::vector<int> heap_;
  long expansions_ = 0;
};

}  // namespace dynamap::planning
