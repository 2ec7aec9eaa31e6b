# The steering lab: build glue. `make demo` serves the lab, `make test` runs every suite.
# Both install what is missing first (idempotent; see ../shared/TOOLCHAIN.md).
SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
export PATH := $(HOME)/.cargo/bin:$(PATH)

WASM_PACK_VERSION := 0.15.1
WASM_BINDGEN_VERSION := $(shell awk '/^name = "wasm-bindgen"$$/{getline; gsub(/"/,"",$$3); print $$3; exit}' Cargo.lock)

.PHONY: setup setup-rust setup-browser test test-native lint table bench demo

setup: setup-rust setup-browser

setup-rust:
	rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown
	rustup component list --installed | grep -q '^clippy' || rustup component add clippy
	rustup component list --installed | grep -q '^rustfmt' || rustup component add rustfmt
	if ! wasm-pack --version 2>/dev/null | grep -q "$(WASM_PACK_VERSION)"; then \
	  cargo install wasm-pack --version $(WASM_PACK_VERSION) --locked; fi
	if ! wasm-bindgen --version 2>/dev/null | grep -q "$(WASM_BINDGEN_VERSION)"; then \
	  cargo install wasm-bindgen-cli --version $(WASM_BINDGEN_VERSION) --force; fi

setup-browser:
	if [ ! -x /usr/bin/chromium ] || [ ! -x /usr/bin/chromedriver ]; then \
	  apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends chromium chromium-driver; fi

lint:
	cargo fmt --all -- --check
	cargo clippy --all-targets -- -D warnings

test-native:
	cargo test --all-targets

test: setup lint test-native
	@echo "make test: all suites passed"

table:
	cargo run --release --bin eta-table -- --out tables/eta.bin

bench:
	cargo bench
