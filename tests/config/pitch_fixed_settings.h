/* pitch_fixed_settings.h - a user's settings file (include/ssda/config.h,
   SSDA_CONFIG_FILE) that fixes the pitch configuration: the reduced core of
   tools/budget.sh, 16 kHz with every other setting its default, whole
   frames (test pitch_fixed_reduced, both sides: the fixed library takes
   the switches, the full one only the settings its program reads). */
#define SSDA_CFG_PITCH_FIXED_RATE_HZ 16000
#define SSDA_CFG_PITCH_FIXED_FLAGS (SSDA_PITCH_NO_FILTER | SSDA_PITCH_NO_OCTAVE | SSDA_PITCH_NO_BELOW_RANGE)
#define PITCH_FIXED_BY_FRAME
#ifdef PITCH_FIXED_SIDE
#define SSDA_CFG_PITCH_FIXED
#define SSDA_CFG_NO_PITCH_FILTER
#define SSDA_CFG_NO_PITCH_TRACK
#define SSDA_CFG_NO_PITCH_FULL
#define SSDA_CFG_NO_PITCH_PARABOLIC
#define SSDA_CFG_NO_PITCH_PUSH
#define SSDA_CFG_NO_PITCH_OCTAVE
#define SSDA_CFG_NO_PITCH_BELOW_RANGE
#endif
