# The steering lab: build glue. `make demo` serves the lab, `make test` runs every suite.
# Both install what is missing first (idempotent; see ../shared/TOOLCHAIN.md).
SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
export PATH := $(HOME)/.cargo/bin:$(PATH)

WASM_PACK_VERSION := 0.15.1
WASM_BINDGEN_VERSION := $(shell awk '/^name = "wasm-bindgen"$$/{getline; gsub(/"/,"",$$3); print $$3; exit}' Cargo.lock)

.PHONY: setup setup-rust setup-rustup setup-rust-tools setup-base tools-done setup-browser setup-web setup-wasm-strip test test-native lint table bench demo \
	wasm web-build web-build-test test-wasm test-smoke test-tsc test-e2e bench-web test-e2e-gallery test-urlfuzz \
	test-e2e-learn test-e2e-teach test-e2e-axe test-e2e-vehicle bench-wasm-native test-e2e-perf bench-tables test-e2e-avoid test-e2e-gpu test-e2e-peers test-protocol bench-budget \
	npm test-npm test-library-user test-lanes test-jobs figures figures-full screenshots stages-start icount

# `make test` says how long each stage took (its own builds included: a
# stage's time runs from the end of the one before to its own end), from
# the stamps each stage appends to target/stages.log.
STAGES_LOG := target/stages.log
stage-done = @mkdir -p target && echo "$$(date +%s) $@" >> $(STAGES_LOG)

setup: setup-rust setup-browser setup-web setup-wasm-strip
	$(stage-done)

# The two tools are built unoptimised (opt-level 0), into one target
# directory, so the second reuses the dependencies the first built with the
# same features: on a new machine their build is the longest part of
# set-up. Measured on an idle 2-core machine: 116 + 122 CPU-s for
# wasm-pack and the CLI; at opt-level 1, each in its own directory, the
# CLI alone took 244. Their own work here stays small: wasm-bindgen takes
# 1.5 s on the largest test module (0.4 s optimised), some fifteen
# modules per `make test`.
TOOL_PROFILE := CARGO_PROFILE_RELEASE_OPT_LEVEL=0 CARGO_TARGET_DIR=target/tools

setup-rust: setup-rustup setup-rust-tools

setup-rustup:
	rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown
	rustup component list --installed | grep -q '^clippy' || rustup component add clippy
	rustup component list --installed | grep -q '^rustfmt' || rustup component add rustfmt

# wasm-pack and the wasm-bindgen CLI, built from crates.io (their release
# binaries come from GitHub, which these machines cannot reach). The CLI
# without its default features: they add a TLS stack (rustls, ring's C
# build) that its test runner never uses here, speaking plain HTTP to
# Debian's ChromeDriver on this machine.
setup-rust-tools:
	if ! wasm-pack --version 2>/dev/null | grep -q "$(WASM_PACK_VERSION)"; then \
	  $(TOOL_PROFILE) cargo install wasm-pack --version $(WASM_PACK_VERSION) --locked; fi
	if ! wasm-bindgen --version 2>/dev/null | grep -q "$(WASM_BINDGEN_VERSION)"; then \
	  $(TOOL_PROFILE) cargo install wasm-bindgen-cli --version $(WASM_BINDGEN_VERSION) --no-default-features --force; fi

setup-browser:
	if [ ! -x /usr/bin/chromium ] || [ ! -x /usr/bin/chromedriver ]; then \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends chromium chromium-driver; fi

# wabt's wasm-strip, from Debian (wasm-pack's own wasm-opt is off: its
# binaries come from GitHub, which these machines cannot reach).
setup-wasm-strip:
	command -v wasm-strip >/dev/null || (apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends wabt)

# Vite 8 does not install with npm 10 (seen on machines where npm's own
# upgrade at boot failed): upgrade npm first, from the npm registry.
setup-web:
	if [ "$$(npm --version | cut -d. -f1)" -lt 11 ]; then npm install -g npm@11 --no-audit --no-fund; fi
	if [ ! -f web/node_modules/.package-lock.json ] || [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then \
	  cd web && npm ci --no-audit --no-fund; fi

# `--features cli,counters`: the command lines and the tests that run them as
# a user does; the table's read counters for the counted cost claims.
# `missing_docs` is denied in the crate root, so clippy refuses an
# undocumented public item; rustdoc's warnings (broken links) fail here too.
lint:
	cargo fmt --all -- --check
	cargo clippy --all-targets --features cli,counters -- -D warnings
	cargo clippy --target wasm32-unknown-unknown --lib --tests -- -D warnings
	cargo clippy --target wasm32-unknown-unknown --lib --no-default-features -- -D warnings
	RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --features cli
	RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --target wasm32-unknown-unknown
	$(stage-done)

# The tests write the figures records into target/figures (cleared first,
# so a renamed test leaves no stale record); then the report's checked
# part (docs/FIGURES.md) must equal what they measured, byte for byte
# (`steer` as the tests built it, target/debug/steer: `cargo run` would
# resolve the features without the dev-dependencies and compile the crate
# and some of its dependencies again, 80 s on a 2-core machine).
test-native:
	rm -rf target/figures
	cargo test --all-targets --features cli,counters
	cargo test --doc --features cli,counters
	$${CARGO_TARGET_DIR:-target}/debug/steer report --check
	$(stage-done)

# The figures report, fast mode (a few minutes): every test that writes a
# figures record (tests/*.rs using tests/common/figures.rs: the fidelity
# tests, the fast studies, the presets run to their end), then
# `steer report` rewrites docs/FIGURES.md and the committed records in
# docs/figures/, the presets' captions are rendered from them, and the
# presets are checked against the report. (`steer` is the binary the
# tests built: the same features, so nothing is compiled twice.) The
# browser's peers rows (web/test/e2e-peers.mjs, Chromium) join them.
FIGURE_TESTS = $(patsubst tests/%.rs,--test %,$(shell grep -l 'common::figures' tests/*.rs))
REPORT_ARGS ?=
figures: setup-browser web-build-test
	rm -rf target/figures
	cargo test --release --features cli,counters $(FIGURE_TESTS) -- --skip presets_show_the_captions
	node web/test/suite.mjs web/test/e2e-peers.mjs --record
	./target/release/steer report --prune $(REPORT_ARGS)
	python3 scenarios/make_presets.py
	cargo test --release --features cli,counters --test figures presets_show_the_captions

# Full mode: the studies at their report sizes and the benchmarks that
# write timed records (benches/*.rs using the figures records), into
# target/figures-full, and the browser's timed peers rows, then the fast
# mode with them (docs/figures/full/).
# The benches' criterion runs are short (1 s warm-up, 2 s per piece): the
# records are their own interleaved same-run ratios, not criterion's times.
FULL_STUDIES := "reach" "relaxed" "relaxed --aim paper-arc" "envelope --n 10000 --seed 2 --brief" "avoid --seeds 100 --seed 0"
FIGURE_BENCHES = $(filter-out icount,$(patsubst benches/%.rs,%,$(shell grep -l 'figures' benches/*.rs)))
figures-full:
	rm -rf target/figures-full
	cargo test --release --features cli,counters --no-run --test figures
	for s in $(FULL_STUDIES); do \
	  FIGURES_DIR=target/figures-full ./target/release/steer $$s --record > /dev/null; done
	for b in $(FIGURE_BENCHES); do \
	  FIGURES_DIR=$(CURDIR)/target/figures-full cargo bench --features cli,counters --bench $$b \
	    -- --warm-up-time 1 --measurement-time 2; done
	$(MAKE) web-build-test
	node web/test/suite.mjs web/test/e2e-peers.mjs --record --full
	$(MAKE) icount
	$(MAKE) figures REPORT_ARGS="--full-records target/figures-full"

# The world's instructions under callgrind (valgrind; benches/icount.rs):
# `world_bench 10000 20 1` whole, and per agent update, on one thread.
# Deterministic for one toolchain and build only: a full-mode record of
# kind `counted` naming the toolchain (into target/figures-full; `make
# figures-full` runs it and reports it). world_bench is built without the
# `counters` feature, as the page's wasm is.
icount:
	cargo build --release --example world_bench
	FIGURES_DIR=$(CURDIR)/target/figures-full cargo bench --bench icount

# The release wasm package the page and the smoke test load (wasm-opt is
# disabled in Cargo.toml: Debian's binaryen corrupts wasm-bindgen output).
#
# A second build with WebAssembly SIMD (`+simd128`, its own target
# directory so the two builds do not invalidate each other) ships beside it
# as web/pkg/steering_simd_bg.wasm; web/src/core/wasm.ts loads it where
# WebAssembly.validate accepts a SIMD instruction, else the baseline. The
# two builds' JavaScript glue must be byte-identical (checked here).
# `--no-default-features`: the pages call no study, so `studies` (and
# anything else on by default for native users) stays out of the download.
SIMD_FLAGS := -C target-feature=+simd128
# The two builds run side by side: each ends in a one-unit LTO link that
# keeps one core busy, so on two cores both take about the time of one.
# Each writes its log under target/; both are printed, and either failing
# fails the target.
WASM_BASE_BUILD := wasm-pack build --target web --release --out-dir web/pkg --no-pack -- --no-default-features
WASM_SIMD_BUILD := CARGO_TARGET_DIR=target/wasm-simd RUSTFLAGS="$(SIMD_FLAGS)" \
	  wasm-pack build --target web --release --out-dir target/wasm-simd/pkg --no-pack -- --no-default-features
# The pages' wasm without its custom sections: the function names (a
# tenth of the module, there for stack traces, and no panic crosses the
# boundary), the producers and target features; they carry no semantics.
wasm: setup-rust setup-wasm-strip
	mkdir -p target/wasm-simd
	( $(WASM_SIMD_BUILD) ) > target/wasm-simd/build.log 2>&1 & simd=$$!; \
	base=0; $(WASM_BASE_BUILD) || base=$$?; \
	simd_rc=0; wait $$simd || simd_rc=$$?; \
	echo "--- the simd128 build (target/wasm-simd/build.log):"; cat target/wasm-simd/build.log; \
	if [ $$base != 0 ] || [ $$simd_rc != 0 ]; then echo "wasm builds failed: baseline exit $$base, simd128 exit $$simd_rc"; exit 1; fi
	cmp web/pkg/steering.js target/wasm-simd/pkg/steering.js
	cp target/wasm-simd/pkg/steering_bg.wasm web/pkg/steering_simd_bg.wasm
	for f in web/pkg/steering_bg.wasm web/pkg/steering_simd_bg.wasm; do wasm-strip $$f; done
	@ls -l web/pkg/steering_bg.wasm | awk '{print "wasm size: " $$5 " bytes"}'
	@gzip -9 -c web/pkg/steering_bg.wasm | wc -c | awk '{print "wasm gzipped: " $$1 " bytes"}'
	@ls -l web/pkg/steering_simd_bg.wasm | awk '{print "wasm (simd128) size: " $$5 " bytes"}'

# web/dist, the shipped build: no test hook in it (checked: HOOK_NAMES, the
# test hooks' globals and their own method names).
HOOK_NAMES := __lab|agentRecord|__crowd|__learn|__wander|perfReset|perfStats|stateHash|stepN|obstacleKnobs|cachedTables|viewScale|simTime|firstFrameMs|tableMs|loadScaled|runSteps|skippedSteps|snapshot|boidsPerFrame|jobMsPerStep|workerMsPerStep|msPerStep|meanWorkMs|p95WorkMs|steppedFrames|coreModes|handleKindAt|peerGhosts|__peers|__gpu
web-build: setup-web wasm
	cd web && npx vite build --logLevel warn
	if grep -rnoE --include='*.js' --include='*.html' '\b($(HOOK_NAMES))\b' web/dist; then echo "web/dist holds test hooks (above)"; exit 1; fi
	$(stage-done)

# web/dist-test: the same pages with their test hooks (`vite build --mode
# test`: window.__lab, __crowd, __learn, __wander), which the browser suites
# and the benches drive.
web-build-test: setup-web wasm
	cd web && npx vite build --mode test --logLevel warn
	$(stage-done)

# The bindings in headless Chromium (webdriver.json carries the flags),
# the golden-hash suites among them. The shipped simd128 module is held to
# the same bits by test-smoke (web/test/simd-bits.mjs: it gives the
# baseline module's bits over every preset) and test-e2e-perf (the lab in
# Chromium on either core), not by a second wasm test build of the crate
# and its dependencies with SIMD on. The test binaries are optimised (opt-level
# 3) without the release profile's whole-program LTO in one codegen unit:
# linking each of some thirty test modules that way was the slowest build
# of `make test`, and it changes no result (no fast-math: the same IEEE
# operations in the same order); the shipped module itself, built with it,
# is what the smoke, e2e and npm suites load.
WASM_TEST_PROFILE := CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16
#
# Only the test files that hold browser tests are built for wasm32 (the
# others are native only, `#![cfg(not(target_arch = "wasm32"))]`, and the
# library's own unit tests are native ones): building them all compiled
# the library once more in its test configuration and ran some forty
# empty binaries.
WASM_TESTS := $(patsubst tests/%.rs,--test %,$(shell grep -l 'wasm_bindgen_test' tests/*.rs))
test-wasm: setup-rust setup-browser
	$(WASM_TEST_PROFILE) wasm-pack test --headless --chrome --release $(WASM_TESTS)
	$(stage-done)

# Loads the *release* package in Node with initSync: catches broken
# post-processing. Then the simd128 module against the baseline, bit for bit.
test-smoke: setup-web wasm
	node web/test/smoke.mjs
	node web/test/simd-bits.mjs
	$(stage-done)

# Seeded fuzz of the lab's URL decoder: 10,000 mutated fragments, each
# decoded state built in the release wasm package (about 11 s);
# URLFUZZ_ARGS="--cases N --seed S" for another run.
URLFUZZ_ARGS ?=
test-urlfuzz: setup-web wasm
	node web/test/urlfuzz.mjs $(URLFUZZ_ARGS)
	$(stage-done)

# The type check, then the web sources' house rules (web/test/source.mjs:
# no function in web/src over 150 lines, no comment naming an issue or a stop).
test-tsc: setup-web wasm
	cd web && npx tsc --noEmit -p tsconfig.json
	cd web && node test/source.mjs
	$(stage-done)

# The workers' continuing-jobs protocol on real threads in Node (~25 s;
# PROTOCOL_ARGS="--frames N").
PROTOCOL_ARGS ?=
test-protocol: setup-web
	cd web && node test/protocol.mjs $(PROTOCOL_ARGS)
	$(stage-done)

# Extra flags for node in the node:test suites below, e.g.
# NODE_TEST_ARGS=--test-name-pattern=drag: only the tests whose name matches
# (the rest reported skipped). Each browser suite runs through
# web/test/suite.mjs: one whose Chromium crashed under it (exit 75, said
# loudly) runs once more from the start; a failed check is never rerun.
NODE_TEST_ARGS ?=

# Playwright (playwright-core + Debian's chromium) against the built page.
test-e2e: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e.mjs
	$(stage-done)

# Playwright against the gallery pages (crowd.html, wander.html); also prints
# the crowd's step cost (boids stepped per 16.7 ms frame at 300/3,000/30,000).
test-e2e-gallery: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-gallery.mjs
	$(stage-done)

# Playwright against the learn page (learn.html): every section
# draws, one handle per section drags and changes its number, the "show in
# the lab" links, no figure playing before Play, the figures held against
# the numbers their paragraphs quote, phone width; screenshots in artifacts/.
test-e2e-learn: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-learn.mjs
	$(stage-done)

# The lab as a learner meets it (1440×900 and 390×844): the legend names the
# core's modes in words, the HUD's mode chip, diagnostics behind a toggle,
# preset titles, every handle's hit area ≥ 24 CSS px on a phone; takes the
# screenshots of the four pages (into artifacts/docs/; `make screenshots`).
test-e2e-teach: setup-browser web-build-test
	node web/test/suite.mjs web/test/e2e-teach.mjs
	$(stage-done)

# axe-core (web/'s pinned devDependency) on the four pages at 1440×900 and
# 390×844: no serious or critical violation; also prints the learn page's
# bytes fetched and first contentful paint. The same pages' visible text
# (and the presets' captions, the gallery's labels) scanned for code words:
# identifiers, file paths, flags (web/test/words.mjs; shown to bite first).
test-e2e-axe: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-axe.mjs
	$(stage-done)

# Playwright for other vehicles: vehicle limits build their η table in Web
# Workers (HUD, URL, IndexedDB cache on reload), presets use the link's limits.
# Then the lab for every hand and eye (web/test/e2e-keys.mjs): every handle by
# keyboard, the crowd section and the measured speed lines (the lab's HUD,
# the crowd page at 200,000 boids), the car-like vehicle's glyph and HUD
# line, touch hit areas, the phone's panel; screenshots in artifacts/keys-*.
test-e2e-vehicle: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-vehicle.mjs
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-keys.mjs
	$(stage-done)

# Avoidance in the lab: the page plays the circle swap and reads the core's
# overlap count (0 with ORCA, > 0 off), the avoidance selector, obstacles
# dragged by mouse and finger, the link; screenshots in artifacts/.
test-e2e-avoid: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-avoid.mjs
	$(stage-done)

# The WebGPU kernel against the core, in Chromium over SwiftShader (a CPU
# emulation: correctness, not speed): one step from states sampled along
# seeded runs (pedestrian, car, robot: modes the same for >= 99.9 %,
# positions, headings, speeds within 1e-4), a free run of 600 steps (every
# agent's arrival verdict the core's), table reads at random probes (within
# 1e-5 rad). Near static goals the kernel follows the core's short-range
# choice (turning first, funnelling slowed), made by the core when the
# world is packed and between steps for goals agents move on to; the suite
# asserts some agents turn first. A planted change to the kernel's μ bound,
# integrator or walk round the disk must fail it. With separation (dense
# pedestrian and robot worlds): the same one-step contract, the GPU-built
# grid against the CPU's counts, free-run verdicts the core's for >= 98 %
# of agents, and a planted change to the push or the prefix sum fails.
# Also prints the timing page's rows, labelled an emulation.
test-e2e-gpu: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-gpu.mjs
	$(stage-done)

# Side by side with the peers in headless Chromium, one page run (the test
# build's peers.html): our core, Yuka 0.7.8 (arrive, seek) and DetourCrowd
# (@recast-navigation/core 0.43.1), web/'s devDependencies, on the same
# seeded oriented targets and circle swaps; prints the rows and writes them
# as figures records (web/test/e2e-peers.mjs::peers_web_*) into
# target/figures, which must equal the committed ones (`make figures`
# measures them anew); then the lab's compare view (both
# arrival headings; screenshots in artifacts/). PEERS_ARGS="--full": also
# the timed rows (cost per agent update at 1,000 / 10,000 / 100,000).
PEERS_ARGS ?=
test-e2e-peers: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-peers.mjs $(PEERS_ARGS)
	$(stage-done)

# Performance paths in the browser: the SIMD core where the engine has SIMD, the
# baseline where it has not; WebGL2 instanced agents above 2,000 (forced with
# ?draw=gl: headless WebGL is software, where the pages keep 2D sprites);
# the lab stepped in Web Workers (shared memory, by message without
# cross-origin isolation, facing pairs) equals one core after 120 steps.
test-e2e-perf: setup-browser web-build-test
	node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/e2e-perf.mjs
	$(stage-done)

# Frame time with 1,000 and 10,000 funnelling agents in headless Chromium,
# then wasm / native per funnelling agent update, and agents
# stepped per 16.7 ms frame at 10k / 30k / 100k with 0, 1 and N workers.
# First the time to the first frame, 9 fresh loads (median, p90, where the
# time went); BENCH_WEB_ARGS="--base DIR" alternates them with another
# build's test dist (web/dist-test), e.g. main's built into /tmp; the rows'
# sizes, rounds and modes are flags too (`node web/test/perf.mjs --help`),
# e.g. BENCH_WEB_ARGS="--only-crowd --crowd-sizes 100000 --crowd-rounds 1".
BENCH_WEB_ARGS ?=
bench-web: setup-browser web-build-test bench-wasm-native
	node web/test/perf.mjs 1000,10000 $(BENCH_WEB_ARGS)

# CPU per drawn state per thread group (the workers, the page's
# thread, the rest; Linux /proc) on the lab at 100,000 agents and the crowd
# at 150,000 / 200,000 boids, and the CPU 100,000 per frame would need
# (BENCH_BUDGET_ARGS="--base DIR": against another build's test dist,
# web/dist-test, same run; a build older than the test mode: its web/dist;
# sizes, rounds and workers are flags too, `node web/test/budget.mjs --help`,
# e.g. BENCH_BUDGET_ARGS="--rounds 3 --lab-sizes 100000 --crowd-sizes '' --workers 2").
BENCH_BUDGET_ARGS ?=
bench-budget: setup-browser web-build-test
	node web/test/budget.mjs $(BENCH_BUDGET_ARGS)

# η table build in Chromium's Web Workers and the cached reload,
# per reference vehicle, 5 fresh contexts each (median, max, host load;
# BENCH_TABLES_ARGS="--reps N").
BENCH_TABLES_ARGS ?=
bench-tables: setup-browser web-build-test
	node web/test/bench-tables.mjs $(BENCH_TABLES_ARGS)

# The same funnelling world natively (diagnostics/world_bench.rs) and
# in Node on the release wasm package, alternating rounds, one run; prints
# the ratio and checks both sides end in the same states.
bench-wasm-native: setup-web wasm
	cargo build --release --example world_bench
	node web/test/wasmnative.mjs 10000
	node web/test/wasmnative.mjs 100000

# The wasm core as an npm package (npm/): the pages' baseline module (built
# once by `make wasm`: no default features, so no studies and no embedded
# table: the package ships eta.bin beside it; stripped of its custom
# sections here too, whatever built it), its typings without the classes'
# `[Symbol.dispose]` (ESNext.Disposable's: a user's `lib: ["es2022",
# "dom"]` has no `Symbol.dispose`), the scenarios (the element's presets),
# the element module <funnel-figure> (web/vite.element.config.ts, from
# web/src/element/), then `npm pack` into target/npm, and the sizes.
npm: setup-web wasm
	rm -rf npm/pkg npm/scenarios && mkdir -p npm/pkg npm/scenarios
	cp web/pkg/steering.js web/pkg/steering.d.ts web/pkg/steering_bg.wasm web/pkg/steering_bg.wasm.d.ts npm/pkg/
	wasm-strip npm/pkg/steering_bg.wasm
	sed -i '/^ *\[Symbol\.dispose\]()/d' npm/pkg/steering.d.ts
	if grep -n 'Symbol.dispose' npm/pkg/steering.d.ts; then echo "npm/pkg/steering.d.ts still names Symbol.dispose"; exit 1; fi
	cp tables/eta.bin npm/eta.bin
	cp scenarios/*.json npm/scenarios/
	cd web && npx vite build --config vite.element.config.ts --logLevel warn
	cp target/npm-element/funnel-figure.js npm/funnel-figure.js
	mkdir -p target/npm
	cd npm && npm pack --pack-destination ../target/npm
	@ls -l target/npm/steering-core-*.tgz | awk '{print "npm tarball: " $$9 ", " $$5 " bytes"}'
	@ls -l npm/pkg/steering_bg.wasm | awk '{print "npm wasm: " $$5 " bytes"}'
	@gzip -9 -c npm/pkg/steering_bg.wasm | wc -c | awk '{print "npm wasm gzipped: " $$1 " bytes"}'
	@ls -l npm/funnel-figure.js | awk '{print "npm element module: " $$5 " bytes"}'
	$(stage-done)

# The tarball installed into a scratch folder under target/ (node:test):
# the example page and a plain page of two <funnel-figure> elements served
# from there alone in Chromium; createLab() in Node without a browser, with
# the cost of single and batched adds; the typings under `tsc --strict`
# with `lib: ["es2022", "dom"]`.
test-npm: setup-web setup-browser npm
	node --test npm/test/*.test.mjs
	$(stage-done)

# A crate that depends on the library as a user's would (examples/library-user:
# default features, its table from the library); fails unless its agents arrive.
test-library-user:
	cargo run --release --manifest-path examples/library-user/Cargo.toml --target-dir target/library-user
	$(stage-done)

# Every browser suite above, the npm package's tests and the library
# user, longest first (web/test/lanes.mjs: each job's output printed whole
# when it ends, its time in target/lanes.log). `make test-lanes` runs them
# two at a time on their own; `make test` runs them after the build lanes
# below, each suite as soon as the wasm lane has built the page and the
# package ($(1) = "@wasm"). The targets above still run one suite each.
# e2e-peers writes its deterministic records into target/figures, which
# test-native clears first and checks last: it starts after the native lane.
comma := ,
LANE_SUITE = $(1)$(2)="node $(NODE_TEST_ARGS) web/test/suite.mjs web/test/$(1).mjs"
LANE_JOBS = $(call LANE_SUITE,e2e-perf,$(1)) $(call LANE_SUITE,e2e-gpu,$(1)) $(call LANE_SUITE,e2e,$(1)) \
	$(call LANE_SUITE,e2e-gallery,$(1)) $(call LANE_SUITE,e2e-vehicle,$(1)) $(call LANE_SUITE,e2e-avoid,$(1)) \
	npm$(1)="node --test npm/test/*.test.mjs" \
	library-user="cargo run --release --manifest-path examples/library-user/Cargo.toml --target-dir target/library-user" \
	$(call LANE_SUITE,e2e-keys,$(1)) $(call LANE_SUITE,e2e-learn,$(1)) $(call LANE_SUITE,e2e-teach,$(1)) \
	$(call LANE_SUITE,e2e-axe,$(1)) $(call LANE_SUITE,e2e-peers,$(if $(1),$(1)$(comma)native))
test-lanes: setup-browser web-build-test npm
	node web/test/lanes.mjs --jobs 2 $(call LANE_JOBS,)
	$(stage-done)

stages-start:
	@mkdir -p target && echo "$$(date +%s) start" > $(STAGES_LOG)

# `make test` after set-up: one run of web/test/lanes.mjs, two jobs at a
# time. First the two build lanes: the native suites (lint, then
# test-native: target/debug) beside the wasm ones and the page's builds
# (target/release, target/wasm-simd, web/), no build directory in
# common, so neither waits on the other's lock. Each lane is its own make,
# with its own stage times (target/stages-native.log,
# target/stages-wasm.log). The native lane needs no wasm tool, so on a new
# machine wasm-pack and the wasm-bindgen CLI are built at the head of the
# wasm lane (setup-rust-tools), beside the native lane's lint. Then the
# jobs of LANE_JOBS, the browser suites starting in whichever lane is free
# once the wasm lane has ended: where it ends first, they fill the
# native lane's single-core stretches (a test binary whose last test runs
# alone) instead of waiting for it.
BUILD_LANES := native="$(MAKE) --no-print-directory stages-start lint test-native STAGES_LOG=target/stages-native.log" \
	wasm="$(MAKE) --no-print-directory stages-start setup-rust-tools tools-done test-wasm test-smoke test-urlfuzz test-tsc test-protocol web-build web-build-test npm STAGES_LOG=target/stages-wasm.log"
tools-done:
	$(stage-done)
test-jobs: setup-rustup setup-web setup-browser
	node web/test/lanes.mjs --jobs 2 $(BUILD_LANES) $(call LANE_JOBS,@wasm)
	$(stage-done)

STAGE_TIMES = awk 'NR > 1 { printf "    %-18s %5d s\n", $$2, $$1 - t } { t = $$1 }' $(1)
# `setup` less the wasm tools' builds (see BUILD_LANES).
setup-base: setup-rustup setup-browser setup-web setup-wasm-strip
	$(stage-done)
test: stages-start setup-base test-jobs
	@awk 'NR > 1 { printf "  %-20s %5d s\n", $$2, $$1 - t } { t = $$1; if (NR == 1) t0 = $$1 } END { printf "  %-20s %5d s (%.1f min)\n", "make test", t - t0, (t - t0) / 60 }' $(STAGES_LOG)
	@echo "  the native lane's stages:"; $(call STAGE_TIMES,target/stages-native.log)
	@echo "  the wasm lane's stages:"; $(call STAGE_TIMES,target/stages-wasm.log)
	@echo "  test-jobs, two at a time (seconds, started at):"; awk '{ printf "    %-18s %5d s  +%d s\n", $$2, $$1, $$4 }' target/lanes.log
	@echo "make test: all suites passed"

demo: setup web-build
	@echo "the steering lab: http://127.0.0.1:5173/"
	cd web && npx vite preview --host 127.0.0.1 --port 5173 --strictPort

# The pictures the repository commits (docs/lab.png, the README's; the four
# pages at both widths in docs/screenshots/): the suites that take them,
# told to write into docs/ (under `make test` they write into
# artifacts/docs/, so a test run leaves the checkout clean).
screenshots: setup-browser web-build-test
	node web/test/suite.mjs web/test/e2e.mjs --docs docs
	node web/test/suite.mjs web/test/e2e-teach.mjs --docs docs

table:
	cargo run --release --features cli --bin eta-table -- --out tables/eta.bin

bench:
	cargo bench
