#pragma once
// Undoing what the lab knows about a channel's acquisition, before the
// conversion to α (link_analysis.cpp), in one FFT of the record (FFTW):
//  - a known sample-time offset: a multiplexed ADC samples channel i a fixed
//    time after the crank channel, a linear-phase anti-alias filter delays
//    the signal; x_k = s(t_k + d) has the transform S(f)·exp(j2πf·d), so the
//    spectrum times exp(−j2πf·d) gives s(t_k) on the crank channel's times;
//  - a known analog response H(f) (acquire/analog_response.hpp: the DAQ's
//    Butterworth filter, the sensor's mounted resonance): divided out where
//    |H| ≥ 0.1 (gain and phase), only its phase removed beyond (no gain above
//    10 on noise; analyze's band-pass keeps well inside in practice).
// The straight line through the record's first and last samples is taken
// out first and shifted exactly (H(0) = 1), so the circular transform sees
// no jump at the record's ends; what is left (ringing within a few hundred
// samples of the ends) lies in analyze's guard revolutions.

#include <span>
#include <vector>

#include "acquire/analog_response.hpp"

namespace fourbar {

/// In place: x_k = (h ∗ s)(t_k + delay_s) in, s(t_k) out. No change for
/// delay 0 without sections, or fewer than 4 samples.
void undo_known_response(std::span<double> x, double sample_rate_hz, double delay_s,
                         const std::vector<AnalogSection>& sections);

}  // namespace fourbar
