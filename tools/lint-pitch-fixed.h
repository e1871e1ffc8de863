/* lint-pitch-fixed.h - a settings file (include/ssda/config.h,
   SSDA_CONFIG_FILE) for tools/lint.sh's pass over the pitch with its
   configuration fixed at compile time (SSDA_CFG_PITCH_FIXED) and every
   part of it built in: push intake, low-pass, tracking, parabola, octave
   and below-range checks, at 8 kHz with every setting given. The reduced
   core's pass reads tests/config/pitch_fixed_settings.h instead. */
#define SSDA_CFG_PITCH_FIXED
#define SSDA_CFG_PITCH_FIXED_RATE_HZ 8000
#define SSDA_CFG_PITCH_FIXED_F0_MIN_HZ 70
#define SSDA_CFG_PITCH_FIXED_F0_MAX_HZ 400
#define SSDA_CFG_PITCH_FIXED_FRAME_LEN 200
#define SSDA_CFG_PITCH_FIXED_HOP 150
#define SSDA_CFG_PITCH_FIXED_CHUNK 7
#define SSDA_CFG_PITCH_FIXED_THRESHOLD_Q15 12000
#define SSDA_CFG_PITCH_FIXED_VOICING_Q15 8000
#define SSDA_CFG_PITCH_FIXED_SILENCE_MAD 20
#define SSDA_CFG_PITCH_FIXED_LOWPASS_HZ 600
#define SSDA_CFG_PITCH_FIXED_FLAGS (SSDA_PITCH_TRACK | SSDA_PITCH_PARABOLIC)
