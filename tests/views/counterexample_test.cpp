// A counterexample page from a real divergence: views/ linked with the impl that carries the
// catalogue's fault blocked-forgets-obstacles (an obstacle counts as a free candidate). conform catches it; the page puts both engines side by side at the step
// where they part, with the first differing field named. The page is kept for the browser test
// and `make pictures` (build/browser-artefacts/counterexample/).
#include <gtest/gtest.h>

#include <filesystem>

#include "conformance/exploration/conform.hpp"
#include "impl/io/atomic_file.hpp"
#include "views/view.hpp"

namespace cx = swarmcheck::conformance::exploration;

TEST(CounterexamplePage, ShowsBothEnginesApartAtTheFirstDifferingStep) {
  const std::filesystem::path dir = std::filesystem::path(SWARMCHECK_ARTEFACTS) / "counterexample";
  std::filesystem::create_directories(dir);
  cx::ConformOptions o;
  o.out_dir = dir.string();
  const cx::ConformReport r = cx::run_conform(o);
  ASSERT_TRUE(r.counterexample.has_value());
  // The page names the trace as given: relative to the artefact folder.
  std::filesystem::current_path(dir);
  const std::string name = std::filesystem::path(r.counterexample->trace_path).filename().string();
  const auto page = swarmcheck::views::view_page(name, {});
  ASSERT_EQ(page.data["kind"], "counterexample");
  const auto& sides = page.data["sides"];
  EXPECT_NE(sides["model"]["record"].dump(), sides["impl"]["record"].dump());
  EXPECT_EQ(page.data["divergence"]["path"], r.counterexample->divergence.path);
  EXPECT_EQ(sides["model"]["record"]["step"], r.counterexample->divergence.step);
  swarmcheck::io::write_file_atomically((dir / "counterexample.html").string(), swarmcheck::views::assemble_page(page));
  std::filesystem::copy_file(r.counterexample->trace_path, dir / "counterexample.jsonl",
                             std::filesystem::copy_options::overwrite_existing);
}
