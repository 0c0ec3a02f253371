#include "dynamap/planning/DStarLite.hpp"

#include <algorithm>

namespace dynamap::planning {

DStarLite::DStarLite(TraversalGrid grid, GridIndex start, GridIndex goal)
    : grid_(std::move(grid)), start_(start), goal_(goal), last_start_(start) {
  Reset();
}

void DStarLite::Reset() {
  const std::size_t n = grid_.penalty.size();
  g_.assign(n, kInfinity);
  rhs_.assign(n, kInfinity);
  key_.assign(n, Key{kInfinity, kInfinity});
  heap_pos_.assign(n, -1);
  heap_.clear();
  km_ = 0.0;
  last_start_ = start_;
  if (!grid_.Contains(goal_)) return;
  const int goal = grid_.Index(goal_);
  rhs_[goal] = 0.0;
  HeapPush(goal, CalculateKey(goal));
}

double DStarLite::Heuristic(int s) const { return OctileDistance(start_, grid_.Cell(s)); }

DStarLite::Key DStarLite::CalculateKey(int s) const {
  const double m = std::min(g_[s], rhs_[s]);
  return {m + Heuristic(s) + km_, m};
}

double DStarLite::BestSuccessorRhs(int s) const {
  const GridIndex u = grid_.Cell(s);
  double best = kInfinity;
  for (const Move& m : kMoves) {
    const double c = grid_.MoveCost(u, m);
    if (c == kInfinity) continue;
    best = std::min(best, c + g_[grid_.Index({u.x + m.dx, u.y + m.dy})]);
  }
  return best;
}

void DStarLite::UpdateVertex(int s) {
  const bool queued = heap_pos_[s] >= 0;
  if (g_[s] != rhs_[s]) {
    if (queued) {
      HeapUpdate(s, CalculateKey(s));
    } else {
      HeapPush(s, CalculateKey(s));
    }
  } else if (queued) {
    HeapRemove(s);
  }
}

void DStarLite::ComputeShortestPath() {
  const int start = grid_.Index(start_);
  const int goal = grid_.Index(goal_);
  while (!heap_.empty()) {
    const int u = heap_[0];
    const Key k_old = key_[u];
    const Key start_key = CalculateKey(start);
    if (!(k_old < start_key) && rhs_[start] <= g_[start]) break;
    const Key k_new = CalculateKey(u);
    if (k_old < k_new) {
      HeapUpdate(u, k_new);
      continue;
    }
    ++expansions_;
    const GridIndex uc = grid_.Cell(u);
    if (g_[u] > rhs_[u]) {
      g_[u] = rhs_[u];
      HeapRemove(u);
      for (const Move& m : kMoves) {
        const double c = grid_.MoveCost(uc, m);
        if (c == kInfinity) continue;
        const int s = grid_.Index({uc.x + m.dx, uc.y + m.dy});
        if (s != goal && c + g_[u] < rhs_[s]) {
          rhs_[s] = c + g_[u];
          UpdateVertex(s);
        }
      }
    } else {
      const double g_old = g_[u];
      g_[u] = kInfinity;
      for (const Move& m : kMoves) {
        const double c = grid_.MoveCost(uc, m);
        if (c == kInfinity) continue;
        const int s = grid_.Index({uc.x + m.dx, uc.y + m.dy});
        // Only predecessors whose best successor was u lose their rhs support.
        if (s != goal && rhs_[s] == c + g_old) {
          rhs_[s] = BestSuccessorRhs(s);
          UpdateVertex(s);
        }
      }
      if (u != goal) rhs_[u] = BestSuccessorRhs(u);
      UpdateVertex(u);
    }
  }
}

GridPath DStarLite::Plan() {
  GridPath result;
  expansions_ = 0;
  if (grid_.Blocked(start_) || grid_.Blocked(goal_)) return result;
  ComputeShortestPath();
  result.expansions = expansions_;
  const int start = grid_.Index(start_);
  if (rhs_[start] == kInfinity) return result;
  GridIndex s = start_;
  result.cells.push_back(s);
  const std::size_t max_steps = grid_.penalty.size();
  while (s != goal_) {
    double best = kInfinity;
    GridIndex next = s;
    for (const Move& m : kMoves) {
      const double c = grid_.MoveCost(s, m);
      if (c == kInfinity) continue;
      const GridIndex v{s.x + m.dx, s.y + m.dy};
      const double through = c + g_[grid_.Index(v)];
      if (through < best) {
        best = through;
        next = v;
      }
    }
    if (best == kInfinity || result.cells.size() > max_steps) {
      result.cells.clear();
      return result;
    }
    s = next;
    result.cells.push_back(s);
  }
  result.found = true;
  result.cost = PathCost(grid_, result.cells);
  return result;
}

void DStarLite::MoveStart(GridIndex start) {
  // Keys already queued were computed with the old start; adding the distance the start
  // moved keeps them lower bounds (the key modifier of the paper).
  km_ += OctileDistance(last_start_, start);
  last_start_ = start;
  start_ = start;
}

void DStarLite::UpdateCells(const std::vector<CellChange>& changes) {
  std::vector<int> touched;
  for (const CellChange& change : changes) {
    grid_.penalty[change.index] = change.penalty;
    // A cell's penalty enters every edge that starts or ends at it and, through the
    // corner-cutting rule, the diagonals beside it: the cell and its 8 neighbours.
    const GridIndex c = grid_.Cell(change.index);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const GridIndex v{c.x + dx, c.y + dy};
        if (grid_.Contains(v)) touched.push_back(grid_.Index(v));
      }
    }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  const int goal = grid_.Contains(goal_) ? grid_.Index(goal_) : -1;
  for (const int s : touched) {
    if (s == goal) continue;
    rhs_[s] = BestSuccessorRhs(s);
    UpdateVertex(s);
  }
}

void DStarLite::SetGoal(GridIndex goal) {
  goal_ = goal;
  Reset();
}

void DStarLite::HeapPush(int s, Key key) {
  key_[s] = key;
  heap_pos_[s] = static_cast<int>(heap_.size());
  heap_.push_back(s);
  SiftUp(heap_pos_[s]);
}

void DStarLite::HeapRemove(int s) {
  const int pos = heap_pos_[s];
  const int last = heap_.back();
  heap_.pop_back();
  heap_pos_[s] = -1;
  if (last == s) return;
  heap_[pos] = last;
  heap_pos_[last] = pos;
  SiftUp(pos);
  SiftDown(heap_pos_[last]);
}

void DStarLite::HeapUpdate(int s, Key key) {
  key_[s] = key;
  SiftUp(heap_pos_[s]);
  SiftDown(heap_pos_[s]);
}

void DStarLite::SiftUp(int pos) {
  while (pos > 0) {
    const int parent = (pos - 1) / 2;
    if (!HeapLess(pos, parent)) break;
    std::swap(heap_[pos], heap_[parent]);
    heap_pos_[heap_[pos]] = pos;
    heap_pos_[heap_[parent]] = parent;
    pos = parent;
  }
}

void DStarLite::SiftDown(int pos) {
  const int n = static_cast<int>(heap_.size());
  while (true) {
    const int left = 2 * pos + 1;
    if (left >= n) break;
    int child = left;
    if (left + 1 < n && HeapLess(left + 1, left)) child = left + 1;
    if (!HeapLess(child, pos)) break;
    std::swap(heap_[pos], heap_[child]);
    heap_pos_[heap_[pos]] = pos;
    heap_pos_[heap_[child]] = child;
    pos = child;
  }
}

}  // namespace dynamap::planning
