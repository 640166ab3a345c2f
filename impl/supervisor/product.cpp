// The n-ary synchronous product, built on the fly: breadth-first from the initial tuple, so only
// accessible tuples are ever stored. Tuples live in one flat array and are found again through an
// open-addressing hash table of ids, and double as the states' names (TupleNames): no per-state
// allocation at all.
#include <algorithm>
#include <map>
#include <optional>

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

  std::size_t size() const { return names_.tuples.size() / k_; }
  const StateId* tuple(StateId id) const { return names_.tuples.data() + std::size_t{id} * k_; }
  // The tuples as the names of the product's states (valid while the table lives and grows).
  const TupleNames& names(const std::vector<const Fsm*>& parts) {
    names_.parts = parts;
    return names_;
  }
  std::vector<StateId> release_tuples() { return std::move(names_.tuples); }

  // The id of `t`; a new id (== size() before) when it was not stored yet.
  StateId find_or_insert(const StateId* t) {
    if (2 * (size() + 1) > slots_.size()) grow();
    std::size_t i = hash(t) & (slots_.size() - 1);
    for (;; i = (i + 1) & (slots_.size() - 1)) {
      const StateId id = slots_[i];
      if (id == kNoState) break;
      if (same(t, tuple(id))) return id;
    }
    const auto id = static_cast<StateId>(size());
    SWARM_DEMAND(id != kNoState);
    names_.tuples.insert(names_.tuples.end(), t, t + k_);
    slots_[i] = id;
    return id;
  }

 private:
  // A plain loop: std::equal becomes a memcmp call, slow for the few ids of a tuple.
  bool same(const StateId* a, const StateId* b) const {
    for (std::size_t i = 0; i < k_; ++i)
      if (a[i] != b[i]) return false;
    return true;
  }
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
  TupleNames names_;            // the tuples, flat, and the parts that name them
  std::vector<StateId> slots_;  // power-of-two size, at most half full
};

// The events a product state enables, in name order, found from the parts' own transitions
// (an event is enabled when every part that has it enables it): O(the parts' transitions there)
// per state instead of O(alphabet), which matters for products of many parts with many events.
class EnabledEvents {
 public:
  EnabledEvents(const std::vector<const Fsm*>& parts, const Alphabet& alphabet)
      : parts_(parts), global_(parts.size()), owners_(alphabet.owners.size()),
        stamp_(alphabet.owners.size(), kNoState), hits_(alphabet.owners.size(), 0) {
    for (EventId e = 0; e < alphabet.owners.size(); ++e) {
      owners_[e] = static_cast<std::uint32_t>(alphabet.owners[e].size());
      for (const auto& [p, le] : alphabet.owners[e]) {
        if (global_[p].size() <= le) global_[p].resize(le + 1);
        global_[p][le] = e;
      }
    }
  }

  // For the tuple t of product state z (each state asked once, z ascending: z is the stamp).
  const std::vector<EventId>& at(const StateId* t, StateId z) {
    found_.clear();
    for (std::size_t p = 0; p < parts_.size(); ++p) {
      const Fsm& f = *parts_[p];
      for (auto i = f.first_edge[t[p]]; i < f.first_edge[t[p] + 1]; ++i) {
        const EventId e = global_[p][f.edge_event[i]];
        if (stamp_[e] != z) {
          stamp_[e] = z;
          hits_[e] = 0;
        }
        if (++hits_[e] == owners_[e]) found_.push_back(e);
      }
    }
    std::sort(found_.begin(), found_.end());
    return found_;
  }

 private:
  const std::vector<const Fsm*>& parts_;
  std::vector<std::vector<EventId>> global_;  // [part][local event]: the product's event id
  std::vector<std::uint32_t> owners_;         // [event]: how many parts have it
  std::vector<StateId> stamp_;                // [event]: the state whose hits_ it holds
  std::vector<std::uint32_t> hits_;           // [event]: parts that enable it there
  std::vector<EventId> found_;
};

// The names of the product states seen so far, kept as 64-bit hashes of their spelling (not as
// strings): a name that stands for two tuples is found by comparing the spellings only when
// two hashes are equal.
class NameCollisions {
 public:
  explicit NameCollisions(const TupleNames& names) : names_(names), slots_(1024, kNoState) {}

  // True when state z's name is the name of an earlier state (each state added once, in order).
  bool repeats_earlier(StateId z) {
    spelling_.clear();
    names_.append(z, spelling_);
    const std::uint64_t h = std::hash<std::string>{}(spelling_);
    if (2 * (hashes_.size() + 1) > slots_.size()) grow();
    std::size_t i = h & (slots_.size() - 1);
    for (; slots_[i] != kNoState; i = (i + 1) & (slots_.size() - 1)) {
      if (hashes_[slots_[i]] != h) continue;
      other_.clear();
      names_.append(slots_[i], other_);
      if (other_ == spelling_) return true;
    }
    slots_[i] = z;
    hashes_.push_back(h);
    return false;
  }

 private:
  void grow() {
    slots_.assign(slots_.size() * 2, kNoState);
    const std::size_t mask = slots_.size() - 1;
    for (StateId id = 0; id < hashes_.size(); ++id) {
      std::size_t i = hashes_[id] & mask;
      while (slots_[i] != kNoState) i = (i + 1) & mask;
      slots_[i] = id;
    }
  }

  const TupleNames& names_;
  std::vector<std::uint64_t> hashes_;  // [state]
  std::vector<StateId> slots_;         // power-of-two size, at most half full
  std::string spelling_, other_;       // reused buffers
};

std::string joined(const std::vector<std::string>& names) {
  std::string out = names[0];
  for (std::size_t i = 1; i < names.size(); ++i) out += " || " + names[i];
  return out;
}

}  // namespace

Product product_with_tuples(const std::vector<const Fsm*>& parts,
                            const std::vector<std::string>& names, std::uint64_t max_bytes) {
  // The library's named product (an Automaton built from it): per state its tuple, name and
  // flags; per transition its event and target, twice.
  WorkBudget budget(max_bytes);
  return product_with_tuples(parts, names, budget, PeakModel{0, 160.0 + 24.0 * static_cast<double>(parts.size()), 16.0});
}

Product product_with_tuples(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names,
                            WorkBudget& budget, const PeakModel& peak, const std::string& where) {
  SWARM_DEMAND(!parts.empty());
  SWARM_DEMAND(parts.size() == names.size());
  const std::size_t k = parts.size();
  Alphabet alphabet = merge_alphabets(parts, names);
  Product result;
  Fsm& out = result.fsm;
  result.names.parts = parts;
  out.event_names = std::move(alphabet.names);
  out.controllable = std::move(alphabet.controllable);
  out.observable = std::move(alphabet.observable);
  out.first_edge.assign(1, 0);
  for (const Fsm* p : parts) {
    SWARM_DEMAND(p->named());
    if (p->state_count() == 0) return result;
  }
  // Names can only collide when a component name contains the separator: check only then.
  bool dotted = false;
  for (const Fsm* p : parts)
    for (const auto& s : p->state_names) dotted = dotted || s.find('.') != std::string::npos;

  TupleTable table(k);
  EnabledEvents enabled(parts, alphabet);
  std::vector<StateId> cur(k, 0), next(k);
  table.find_or_insert(cur.data());
  const TupleNames& spelled = table.names(parts);
  std::optional<NameCollisions> collisions;
  if (dotted) collisions.emplace(spelled);
  const std::string named = where.empty() ? joined(names) : where;
  const auto check = [&](StateId z) {
    budget.check(named, peak.at(static_cast<double>(table.size()), static_cast<double>(out.edge_event.size())), [&] {
      return "the product stopped after exploring " + std::to_string(z) + " states (" + std::to_string(table.size()) +
             " found, " + std::to_string(out.edge_event.size()) + " transitions)";
    });
  };
  for (StateId z = 0; z < table.size(); ++z) {  // ids are handed out in breadth-first order
    if (z % 4096 == 0) check(z);
    std::copy(table.tuple(z), table.tuple(z) + k, cur.begin());
    bool marked = true;
    for (std::size_t p = 0; p < k; ++p) marked = marked && parts[p]->marked[cur[p]];
    out.marked.push_back(marked ? 1 : 0);
    if (collisions && collisions->repeats_earlier(z))
      throw InputError(joined(names),
                       "product state name '" + spelled.name(z) +
                           "' stands for two pairs of states; rename states so that no name "
                           "contains '.'");
    for (const EventId e : enabled.at(cur.data(), z)) {
      next = cur;
      for (const auto& [p, le] : alphabet.owners[e]) next[p] = parts[p]->successor(cur[p], le);
      out.edge_event.push_back(e);
      out.edge_target.push_back(table.find_or_insert(next.data()));
    }
    out.first_edge.push_back(static_cast<std::uint32_t>(out.edge_event.size()));
  }
  budget.note(peak.at(static_cast<double>(table.size()), static_cast<double>(out.edge_event.size())));   // what it came to
  result.names.tuples = table.release_tuples();
  return result;
}

Fsm product(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names,
            std::uint64_t max_bytes) {
  Product p = product_with_tuples(parts, names, max_bytes);
  store_names(p.fsm, p.names);
  return std::move(p.fsm);
}

Fsm product(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names, WorkBudget& budget,
            const PeakModel& peak) {
  Product p = product_with_tuples(parts, names, budget, peak);
  store_names(p.fsm, p.names);
  return std::move(p.fsm);
}

}  // namespace swarmcheck::impl::supervisor
