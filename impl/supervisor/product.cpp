// The n-ary synchronous product, built on the fly: breadth-first from the initial tuple, so only
// accessible tuples are ever stored. Tuples live in one flat array and are found again through an
// open-addressing hash table of ids (no per-state allocation besides the name).
#include <map>

#include "impl/supervisor/operations.hpp"
#include "spec/util/demand.hpp"
#include "spec/util/budget.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

std::string attr_words(bool c, bool o) {
  return std::string(c ? "controllable" : "uncontrollable") + " and " +
         (o ? "observable" : "unobservable");
}

// Global alphabet in name order; owners[e] lists (part, local event id) of the parts that have e.
struct Alphabet {
  std::vector<std::string> names;
  std::vector<std::uint8_t> controllable, observable;
  std::vector<std::vector<std::pair<std::size_t, EventId>>> owners;
};

Alphabet merge_alphabets(const std::vector<const Fsm*>& parts,
                         const std::vector<std::string>& names) {
  std::map<std::string, std::size_t> first_owner;
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (EventId e = 0; e < parts[p]->event_count(); ++e) {
      const auto [it, inserted] = first_owner.emplace(parts[p]->event_names[e], p);
      if (inserted) continue;
      const Fsm& q = *parts[it->second];
      const EventId qe = q.event_id(it->first);
      if (q.controllable[qe] != parts[p]->controllable[e] ||
          q.observable[qe] != parts[p]->observable[e])
        throw InputError(names[p], "event '" + it->first + "' is " +
                                       attr_words(parts[p]->controllable[e],
                                                  parts[p]->observable[e]) +
                                       " here but " +
                                       attr_words(q.controllable[qe], q.observable[qe]) +
                                       " in " + names[it->second]);
    }
  Alphabet a;
  for (const auto& [name, p] : first_owner) {
    const Fsm& q = *parts[p];
    const EventId qe = q.event_id(name);
    a.names.push_back(name);
    a.controllable.push_back(q.controllable[qe]);
    a.observable.push_back(q.observable[qe]);
    auto& own = a.owners.emplace_back();
    for (std::size_t r = 0; r < parts.size(); ++r) {
      const EventId re = parts[r]->event_id(name);
      if (re != UINT32_MAX) own.emplace_back(r, re);
    }
  }
  return a;
}

// Tuples of k state ids, stored flat, found by an open-addressing table of ids.
class TupleTable {
 public:
  explicit TupleTable(std::size_t k) : k_(k), slots_(1024, kNoState) {}

  std::size_t size() const { return tuples_.size() / k_; }
  const StateId* tuple(StateId id) const { return tuples_.data() + std::size_t{id} * k_; }

  // The id of `t`; a new id (== size() before) when it was not stored yet.
  StateId find_or_insert(const StateId* t) {
    if (2 * (size() + 1) > slots_.size()) grow();
    std::size_t i = hash(t) & (slots_.size() - 1);
    for (;; i = (i + 1) & (slots_.size() - 1)) {
      const StateId id = slots_[i];
      if (id == kNoState) break;
      if (std::equal(t, t + k_, tuple(id))) return id;
    }
    const auto id = static_cast<StateId>(size());
    SWARM_DEMAND(id != kNoState);
    tuples_.insert(tuples_.end(), t, t + k_);
    slots_[i] = id;
    return id;
  }

 private:
  std::size_t hash(const StateId* t) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::size_t i = 0; i < k_; ++i) {
      h ^= t[i];
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 32;
    }
    return static_cast<std::size_t>(h);
  }
  void grow() {
    std::vector<StateId> bigger(slots_.size() * 2, kNoState);
    slots_.swap(bigger);
    for (StateId id = 0; id < size(); ++id) {
      std::size_t i = hash(tuple(id)) & (slots_.size() - 1);
      while (slots_[i] != kNoState) i = (i + 1) & (slots_.size() - 1);
      slots_[i] = id;
    }
  }

  std::size_t k_;
  std::vector<StateId> tuples_;
  std::vector<StateId> slots_;  // power-of-two size, at most half full
};

std::string tuple_name(const std::vector<const Fsm*>& parts, const StateId* t) {
  std::string name = parts[0]->state_names[t[0]];
  for (std::size_t p = 1; p < parts.size(); ++p) (name += '.') += parts[p]->state_names[t[p]];
  return name;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out = names[0];
  for (std::size_t i = 1; i < names.size(); ++i) out += " || " + names[i];
  return out;
}

}  // namespace

Fsm product(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names,
            std::vector<std::vector<StateId>>* origin, std::uint64_t max_bytes) {
  SWARM_DEMAND(!parts.empty());
  SWARM_DEMAND(parts.size() == names.size());
  const std::size_t k = parts.size();
  Alphabet alphabet = merge_alphabets(parts, names);
  Fsm out;
  out.event_names = std::move(alphabet.names);
  out.controllable = std::move(alphabet.controllable);
  out.observable = std::move(alphabet.observable);
  out.first_edge.assign(1, 0);
  if (origin) origin->clear();
  for (const Fsm* p : parts)
    if (p->state_count() == 0) return out;
  // Names can only collide when a component name contains the separator: check only then.
  bool dotted = false;
  for (const Fsm* p : parts)
    for (const auto& s : p->state_names) dotted = dotted || s.find('.') != std::string::npos;
  std::map<std::string, StateId> seen_names;

  TupleTable table(k);
  std::vector<StateId> cur(k, 0), next(k);
  table.find_or_insert(cur.data());
  // The estimate: per state its tuple (table and origin), name and flags, and what the caller
  // builds from it (a named Automaton); per transition its event and target, twice.
  const double state_bytes = 160.0 + 24.0 * static_cast<double>(k);
  for (StateId z = 0; z < table.size(); ++z) {  // ids are handed out in breadth-first order
    if (max_bytes != 0 && z % 4096 == 0) {
      const double estimate = static_cast<double>(table.size()) * state_bytes + 16.0 * static_cast<double>(out.edge_event.size());
      if (estimate > static_cast<double>(max_bytes))
        throw BudgetExceeded(joined(names), "the product stopped after exploring " + std::to_string(z) + " states (" +
                                                std::to_string(table.size()) + " found, " + std::to_string(out.edge_event.size()) +
                                                " transitions): about " + format_bytes(estimate) + " and growing, over the limit of " +
                                                format_bytes(static_cast<double>(max_bytes)) +
                                                " (raise it with --memory-limit, e.g. --memory-limit 64G)");
    }
    std::copy(table.tuple(z), table.tuple(z) + k, cur.begin());
    bool marked = true;
    for (std::size_t p = 0; p < k; ++p) marked = marked && parts[p]->marked[cur[p]];
    out.state_names.push_back(tuple_name(parts, cur.data()));
    out.marked.push_back(marked ? 1 : 0);
    if (dotted && !seen_names.emplace(out.state_names.back(), z).second)
      throw InputError(joined(names),
                       "product state name '" + out.state_names.back() +
                           "' stands for two pairs of states; rename states so that no name "
                           "contains '.'");
    if (origin) origin->emplace_back(cur.begin(), cur.end());
    for (EventId e = 0; e < out.event_count(); ++e) {
      next = cur;
      bool possible = true;
      for (const auto& [p, le] : alphabet.owners[e]) {
        next[p] = parts[p]->successor(cur[p], le);
        if (next[p] == kNoState) {
          possible = false;
          break;
        }
      }
      if (!possible) continue;
      out.edge_event.push_back(e);
      out.edge_target.push_back(table.find_or_insert(next.data()));
    }
    out.first_edge.push_back(static_cast<std::uint32_t>(out.edge_event.size()));
  }
  return out;
}

}  // namespace swarmcheck::impl::supervisor
