# The two commands of the README, plus the build they share.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)

.PHONY: all deps build demo test clean

all: build

deps:
	@scripts/install-deps

build: deps
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DPENUMBRA_WERROR=ON >/dev/null
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# The main job: render the default scene and write the images under out/.
demo: build
	@scripts/demo $(BUILD_DIR)/penumbra out

test: build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR) out
