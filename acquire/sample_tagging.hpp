#pragma once
// Pass 3 of acquire: reads the recording once more and hands each frame's
// calibrated accelerometer values, and whether any of them is clipped, to the
// RevolutionBuilder, which tags them with the crank motion and resamples each
// planned revolution onto the crank-angle grid (revolution_builder.hpp).

#include <cstddef>
#include <span>
#include <vector>

#include "acquire/channel_inputs.hpp"
#include "acquire/revolution.hpp"
#include "acquire/revolution_builder.hpp"
#include "acquire/signal_excerpt.hpp"
#include "acquire/streaming_pass.hpp"

namespace fourbar {

/// Builds every planned revolution into `sink`; `excerpt` (optional) sees
/// every block. Returns the number of revolutions marked clipped.
std::size_t tag_pass(const BlockStream& stream, std::vector<RevolutionPlan> plan, const GridSettings& grid,
                     std::span<const AccelerometerInput> accelerometers, const ClipRange& clip,
                     AcquisitionSink& sink, ExcerptRecorder* excerpt = nullptr);

}  // namespace fourbar
