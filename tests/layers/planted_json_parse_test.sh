#!/usr/bin/env bash
# The JSON-reader check is itself checked: a scratch tree whose only parse is in the reader
# passes; each planted raw parse (through Json, nlohmann::json, ordered_json, an alias, sax_parse,
# accept, a _json literal, a stream into a json) makes it fail naming the file and line, in every
# layer it covers; tests/ may parse what swarmcheck printed.
set -u
check="$1/scripts/check-json-reader"
tree=$(mktemp -d); trap 'rm -rf "$tree"' EXIT
mkdir -p "$tree"/{spec/util,spec/a,impl/a,apps/a,fmi/a,conformance/a,views/a,proofs/a,fuzz,tests/a}
echo '  Json::sax_parse(text, &builder);' > "$tree/spec/util/json_text.hpp"
echo '  const auto j = nlohmann::json::parse(raw, nullptr, false);' > "$tree/spec/util/json_structure.hpp"
echo 'const Json j = json_io::parse_json_text(text, file);' > "$tree/impl/a/i.cpp"
echo 'const auto j = nlohmann::json::parse(out);   // a test reads what the CLI printed' > "$tree/tests/a/t.cpp"
"$check" "$tree" > /dev/null || { echo "FAIL: a clean tree was rejected"; exit 1; }

plant() {   # plant FILE LINE: add LINE to FILE in the tree; the check must fail naming FILE:1
  local file=$1 line=$2 saved; saved=$(cat "$tree/$file" 2>/dev/null || true)
  printf '%s\n%s\n' "$line" "$saved" > "$tree/$file"
  out=$("$check" "$tree"); rc=$?
  if [ $rc -ne 1 ] || ! grep -q "^$file:1:" <<<"$out"; then
    echo "FAIL: planted '$line' in $file: exit $rc, output: $out"; exit 1
  fi
  if [ -n "$saved" ]; then printf '%s\n' "$saved" > "$tree/$file"; else rm "$tree/$file"; fi
  echo "caught: $file: $line"
}
plant apps/a/v.cpp '  const Json h = Json::parse(first, nullptr, false);'
plant impl/a/i.cpp '  const auto j = json_io::Json::parse(line, nullptr, false);'
plant fmi/a/f.cpp '  const json_io::Json j = json_io::Json::parse(text, nullptr, false);'
plant conformance/a/c.cpp '  auto j = nlohmann::ordered_json::parse(in);'
plant views/a/s.cpp '      j = nlohmann::json::parse(req.body);'
plant proofs/a/p.cpp '    from_json(JsonDoc::parse(text), r);'
plant spec/a/x.hpp '  nlohmann::json::sax_parse(text, &sax);'
plant spec/a/x.hpp '  if (!nlohmann::json::accept(text)) return;'
plant apps/a/v.cpp '  auto j = nlohmann::basic_json<std::map>::parse(text);'
plant impl/a/i.cpp '  const auto j = R"({"a": 1})"_json;'
plant fuzz/f.cpp '  in >> json;'
plant impl/a/i.cpp '  const auto b = nlohmann::json::from_cbor(bytes);'
"$check" "$tree" > /dev/null || { echo "FAIL: the restored tree was rejected"; exit 1; }
echo "every planted raw parse was caught"
