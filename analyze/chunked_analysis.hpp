#pragma once
// The streaming part of analyze_recording (pipeline.hpp): an AcquisitionSink
// that buffers acquire's angle-tagged samples of the current pulse-train
// segment and analyses them in chunks of K whole revolutions with RecordAnalyzer.
//
// A chunk spans its K revolutions plus `overlap` samples on each side
// (half the filter kernel and the resampler's stencil), so each of its
// revolutions sees the same filtered values as a filter over the whole
// segment would give. The segment's own ends are continued periodically in
// the crank angle (the first and last revolution repeated), so the filter
// does not ring there. With the ideal (bin-wise) filter each chunk is one
// period instead, as the thesis did with its record.
// Only the chunk's own revolutions are kept; the buffer then drops what the
// next chunk no longer needs. Memory: about (K revolutions + 2·overlap)
// samples × (3 crank values + the channels used) doubles, plus one chunk's
// working arrays.
//
// Chunks on several cores (AnalyzeOptions::threads > 1): a chunk's
// transform depends only on its own samples, so each chunk's samples are
// copied and transformed on a thread of its own, at most `threads` at once,
// while acquire fills the next one. What carries from chunk to chunk (the
// spectra, the running-trapezoid ω, the guard revolutions, the averages, the
// observer) is done by the calling thread, chunk by chunk in order, so the
// result is bit for bit the one of one thread. Memory: `threads` more copies
// of a chunk's samples and working arrays.
//
// Nothing of a chunk's size is allocated chunk by chunk: the segment
// buffers, the workspaces (filter blocks and FFTW buffers, the grid and the
// working arrays) and the chunks' outcomes go back to pools when a chunk is
// done and are refilled by the next, so their memory is paged in once
// (fresh pages for every chunk cost the kernel as much as a tenth of the
// analysis, and more with chunks on several threads).
//
// The class is split by concept, one file each:
//   chunked_analysis.cpp   the driver: settings into members (analysis_settings,
//                          chunk_plan), filter blocks, averagers, result layout
//   chunk_stitching.cpp    the segment buffer: samples in, chunks out, what the
//                          next chunk keeps, segment ends
//   chunk_transform.cpp    one chunk: convert, filter, integrate, resample
//   chunk_dispatch.cpp     chunks in order: in the calling thread, or on
//                          worker threads and delivered in order
//   revolution_results.cpp guard revolutions, averages, the finished result

#include <deque>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "analyze/analysis_channels.hpp"
#include "analyze/link_analysis.hpp"
#include "analyze/pipeline.hpp"
#include "analyze/spectrum.hpp"

namespace fourbar {

class ChunkedAnalysis final : public AcquisitionSink {
 public:
  /// Fills `result` as the data come. `manifest` and `observer` must outlive it.
  ChunkedAnalysis(RecordingAnalysis& result, const Manifest& manifest, AnalysisChannels channels,
                  RevolutionObserver* observer);
  ~ChunkedAnalysis() override;

  void on_plan(const AcquisitionReport& report) override;
  void on_samples(const SampleBlock& block) override;
  void on_revolution(const Revolution& revolution) override;
  /// The analysis resamples on its own grid, after the filter: acquire makes none.
  bool wants_grid() const override { return false; }
  /// After acquire: analyses what is left and completes the result.
  void finish();

 private:
  /// One chunk's samples: spans into the segment buffer (one thread), or
  /// into `owned` (the buffer handed to a worker thread).
  struct ChunkJob {
    std::size_t rev_begin = 0, rev_end = 0;  ///< the chunk's own revolutions [rev_begin, rev_end)
    std::size_t c0 = 0, c1 = 0;              ///< their samples within the chunk
    std::size_t stream_at = 0;               ///< sample c0 within the segment (the spectra's stream)
    bool at_start = false, segment_end = false;
    std::vector<std::vector<double>> owned;  ///< the detached buffer: θ, ω2, α2, then the used channels
    std::span<const double> theta, speed, accel;
    std::vector<std::span<const double>> samples;  ///< per used channel
  };
  /// One chunk's transform, waiting to be delivered in order.
  struct ChunkOutcome {
    std::size_t rev_begin = 0, rev_end = 0;
    bool segment_end = false;
    long first_revolution = 0;
    std::size_t revolutions = 0;
    std::vector<double> speed;                          ///< revolutions × N
    std::vector<LinkGrids> grids;                       ///< per link
    std::vector<std::vector<double>> normal_grid;       ///< per link (empty without a normal channel)
    std::vector<std::vector<double>> spectrum_samples;  ///< per link: α before the filter over [c0, c1)
    std::vector<SpectrumAverager::SegmentPowers> spectrum_powers;  ///< per link: the segments inside them
    // Running trapezoid only: ω per sample before its start value is known
    // (it carries from the previous chunk), the nominal ω at c0, the grid.
    std::vector<std::vector<double>> omega_samples;
    std::vector<double> nominal_start_omega;
    std::size_t c0 = 0, c1 = 0;
    std::optional<RevolutionResampler> resampler;
  };
  /// A worker's filter blocks, grid and working arrays (one per chunk in
  /// flight), made once and reused chunk after chunk.
  struct ChunkWorkspace {
    std::unique_ptr<FftFilter> alpha_filter, normal_filter;  // windowed: linear convolution, made once
    std::optional<RecordAnalyzer> analyzer;                   // the chunk's grid (reset per chunk)
    std::unique_ptr<RealFft> spectrum_fft;                    // the spectrum segments' transform
    std::vector<double> alpha, unfiltered, w2;
  };

  /// One revolution of a chunk on the grid, waiting to be committed.
  struct Pending {
    std::size_t number = 0;
    std::size_t index_in_segment = 0;  // 0 for the segment's first revolution
    bool leading_guard = false;
    std::vector<double> speed;
    std::vector<std::vector<double>> alpha, omega, omega_sq;  // per link; omega_sq empty without a normal channel
  };

  // chunked_analysis.cpp
  void resolve_settings(const AcquisitionReport& report);
  std::unique_ptr<ChunkWorkspace> make_workspace() const;
  void make_spectra(std::size_t segment_frames);
  void make_averagers();
  // revolution_results.cpp
  void hold_for_repeat(const Pending& rev, bool averaged);
  void lay_out_result(std::size_t taps);
  // chunk_stitching.cpp
  void process_ready();
  /// Drops the buffered samples no chunk from revolution `rev` on needs;
  /// `detached`: the buffer was handed to a chunk (detach_buffer) and is
  /// empty: what is kept is copied back from there.
  void keep_from(std::size_t rev, const std::vector<std::vector<double>>* detached = nullptr);
  void end_segment();
  std::size_t rev_start(std::size_t rev) const;
  // chunk_dispatch.cpp
  void process_chunk(std::size_t rev_end, bool segment_end);
  /// The chunk ending at revolution `rev_end`, as spans into the buffer.
  ChunkJob make_job(std::size_t rev_end, bool segment_end) const;
  /// The segment buffer's vectors (θ, ω2, α2, the used channels), swapped
  /// for emptied spare ones.
  std::vector<std::vector<double>> detach_buffer();
  /// Delivers the chunks in flight, in order: all of them, or (`wait` false)
  /// those finished at the front.
  void drain(bool wait);
  std::unique_ptr<ChunkWorkspace> take_workspace();
  void give_back(std::unique_ptr<ChunkWorkspace> w);
  // chunk_transform.cpp
  /// The chunk's transform into `out` (an outcome of an earlier chunk
  /// reused, or new): reads only the job, the settings and `w`, so chunks
  /// may run on several threads at once.
  void transform(const ChunkJob& job, ChunkWorkspace& w, ChunkOutcome& out) const;
  /// What carries over from chunk to chunk, in order; the outcome then goes
  /// back to the pool.
  void deliver(std::unique_ptr<ChunkOutcome> outcome);
  std::unique_ptr<ChunkOutcome> take_outcome();
  /// Filters one chunk's values in place; a segment end is continued
  /// periodically in the crank angle first (crank_periodic_extension).
  void filter(bool normal, std::span<const double> angle, std::span<double> x, bool at_start, bool at_end,
              ChunkWorkspace& w) const;
  // revolution_results.cpp
  void accept(Pending&& rev);
  void commit(Pending& rev, bool averaged);

  RecordingAnalysis& result_;
  const Manifest& manifest_;
  AnalysisChannels channels_;
  RevolutionObserver* observer_;
  bool planned_ = false;

  // Settings (resolved in on_plan).
  double fs_ = 0, direction_ = 1, offset_rad_ = 0, mean_speed_rad_s_ = 0;
  AngleGridSpec grid_;
  FilterSpec filter_, normal_filter_;
  std::size_t half_kernel_ = 0, overlap_ = 0, chunk_revs_ = 0;
  std::size_t filter_block_frames_ = 0;  // windowed filter: length of the filter blocks
  bool has_normal_ = false;
  std::shared_ptr<const RigTables> tables_;
  std::vector<std::size_t> used_;  // acquire channel indices buffered, in order

  // The current segment's samples from absolute index `base_` on.
  std::vector<double> theta_, speed_, accel_;
  std::vector<std::vector<double>> samples_;  // per used channel
  std::size_t base_ = 0, end_ = 0;           // absolute indices within the segment
  std::deque<std::size_t> starts_;           // absolute index of the first sample of revolutions first_rev_ …
  std::size_t first_rev_ = 0, next_rev_ = 0;
  std::optional<std::int64_t> last_rev_;
  double last_time_ = 0;
  bool in_segment_ = false;
  std::size_t revs_in_segment_ = 0;
  std::vector<std::optional<double>> omega_carry_;  // per link: running-trapezoid ω at next_rev_'s start

  // Results as they accumulate.
  std::vector<bool> clipped_;  // by revolution number
  std::deque<std::unique_ptr<Pending>> guard_queue_;
  std::unique_ptr<SynchronousAverager> speed_avg_;
  std::vector<SynchronousAverager> alpha_avg_, omega_avg_, normal_avg_, omega_sq_avg_;
  std::vector<TurnRepeatAccumulator> alpha_repeat_;  // per link, over the averaged turns away from the segment ends
  struct HeldTurn {
    std::size_t number = 0;
    std::vector<std::vector<double>> alpha;  // per link
  };
  std::deque<HeldTurn> repeat_held_;                 // averaged turns not yet kTurnRepeatEdgeTurns from the segment end
  std::optional<std::size_t> repeat_last_added_;     // number of the last turn added to alpha_repeat_
  std::vector<std::unique_ptr<SpectrumAverager>> spectra_;

  // Chunks on worker threads (chunk_dispatch.cpp). Declared last: the
  // destructor waits for the chunks in flight before anything they read goes.
  std::size_t threads_ = 1;
  std::mutex workspace_mutex_;
  std::vector<std::unique_ptr<ChunkWorkspace>> spare_workspaces_;
  std::vector<std::vector<std::vector<double>>> spare_buffers_;  // detached buffers, back from their chunks
  std::vector<std::unique_ptr<ChunkOutcome>> spare_outcomes_;    // delivered outcomes, to be filled again
  std::deque<std::future<std::unique_ptr<ChunkOutcome>>> in_flight_;
};

}  // namespace fourbar
