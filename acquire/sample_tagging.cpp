#include "acquire/sample_tagging.hpp"

namespace fourbar {

std::size_t tag_pass(const BlockStream& stream, std::vector<RevolutionPlan> plan, const GridSettings& grid,
                     std::span<const AccelerometerInput> accelerometers, const ClipRange& clip,
                     AcquisitionSink& sink, ExcerptRecorder* excerpt) {
  const auto channels = static_cast<std::size_t>(stream.reader.info().channels);
  RevolutionBuilder builder(std::move(plan), grid, accelerometers.size(), sink);
  std::vector<double> calibrated(accelerometers.size());
  for_each_block(stream, AcquirePass::samples, [&](std::span<const double> block, std::size_t frames,
                                                   std::uint64_t first) {
    for (std::size_t f = 0; f < frames; ++f) {
      const double* frame = block.data() + f * channels;
      bool clipped = false;
      for (std::size_t a = 0; a < accelerometers.size(); ++a) {
        const double raw = frame[accelerometers[a].index];
        calibrated[a] = raw * accelerometers[a].m_s2_per_unit;
        clipped |= clip.clipped(raw);
      }
      builder.push(static_cast<std::int64_t>(first + f), calibrated.data(), clipped);
    }
    builder.flush_samples();
    if (excerpt) excerpt->take(block, frames, first, channels);
  });
  builder.finish();
  return builder.revolutions_clipped();
}

}  // namespace fourbar
