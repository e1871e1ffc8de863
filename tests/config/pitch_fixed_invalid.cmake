# pitch_fixed_invalid.cmake - the compile-time checks of a fixed pitch
# configuration (SSDA_CFG_PITCH_FIXED, lib/pitch_config.c): lib/pitch_config.c
# compiled with each setting the full build's ssda_pitch_init refuses must
# fail, naming the check (the array ssda__pitch_fixed_<check>), and a valid
# setting must compile (so the failures are the checks', not the command's).
# A case: "name|check|SETTING=value,SETTING=value,+OTHER_DEFINE".
# Usage: cmake -DCC=compiler -DROOT=source-dir -DOUT=object -P pitch_fixed_invalid.cmake
set(_cases
  "valid|ok|RATE_HZ=16000"
  "rate below 8000|rate|RATE_HZ=7999"
  "rate above 48000|rate|RATE_HZ=48001"
  "f0_min below 10|f0_range|RATE_HZ=16000,F0_MIN_HZ=9"
  "f0_max above rate / 4|f0_range|RATE_HZ=8000,F0_MAX_HZ=2001"
  "f0_min not below f0_max|f0_range|RATE_HZ=16000,F0_MIN_HZ=300,F0_MAX_HZ=300"
  "threshold above 32767|thresholds|RATE_HZ=16000,THRESHOLD_Q15=32768"
  "voicing above 32767|thresholds|RATE_HZ=16000,VOICING_Q15=40000"
  "lowpass above rate / 4|lowpass|RATE_HZ=16000,LOWPASS_HZ=4001"
  "unknown flag|flags_known|RATE_HZ=16000,FLAGS=0x40"
  "frame below 16|frame_len|RATE_HZ=16000,FRAME_LEN=15"
  "frame above 8192|frame_len|RATE_HZ=16000,FRAME_LEN=8193"
  "chunk above the frame|chunk|RATE_HZ=16000,FRAME_LEN=100,CHUNK=101"
  "hop wider than its field|fields|RATE_HZ=16000,HOP=65536"
  "f0_min wider than its field|fields|RATE_HZ=16000,F0_MIN_HZ=65536"
  "f0_max wider than its field|fields|RATE_HZ=16000,F0_MAX_HZ=65536"
  "frame wider than its field|fields|RATE_HZ=16000,FRAME_LEN=65536"
  "silence wider than its field|fields|RATE_HZ=16000,SILENCE_MAD=65536"
  "silence negative|fields|RATE_HZ=16000,SILENCE_MAD=-1"
  "chunk wider than its field|fields|RATE_HZ=16000,CHUNK=65536"
  "low-pass wider than its field|fields|RATE_HZ=16000,LOWPASS_HZ=65536"
  "threshold negative|thresholds|RATE_HZ=16000,THRESHOLD_Q15=-1"
  "rate wider than 32 bits|fields|RATE_HZ=4294983296"
  "threshold wider than 32 bits|fields|RATE_HZ=16000,THRESHOLD_Q15=4294967396"
  "voicing wider than 32 bits|fields|RATE_HZ=16000,VOICING_Q15=4294967396"
  "silence wider than 32 bits|fields|RATE_HZ=16000,SILENCE_MAD=4294967312"
  "flags wider than 32 bits|fields|RATE_HZ=16000,FLAGS=4294967296"
  "chunk above the default frame|chunk|RATE_HZ=16000,CHUNK=321"
  "low-pass in a build without it|no_filter|RATE_HZ=16000,FLAGS=0,+SSDA_CFG_NO_PITCH_FILTER"
  "tracking in a build without it|no_track|RATE_HZ=16000,FLAGS=0x01,+SSDA_CFG_NO_PITCH_TRACK"
  "full search in a build without it|no_full|RATE_HZ=16000,FLAGS=0x02,+SSDA_CFG_NO_PITCH_FULL"
  "parabola in a build without it|no_parabolic|RATE_HZ=16000,FLAGS=0x08,+SSDA_CFG_NO_PITCH_PARABOLIC"
  "octave check in a build without it|no_octave|RATE_HZ=16000,FLAGS=0,+SSDA_CFG_NO_PITCH_OCTAVE"
  "below-range check in a build without it|no_below_range|RATE_HZ=16000,FLAGS=0,+SSDA_CFG_NO_PITCH_BELOW_RANGE"
  "every switch with the flags it needs|ok|RATE_HZ=16000,FLAGS=0x34,+SSDA_CFG_NO_PITCH_FILTER,+SSDA_CFG_NO_PITCH_TRACK,+SSDA_CFG_NO_PITCH_FULL,+SSDA_CFG_NO_PITCH_PARABOLIC,+SSDA_CFG_NO_PITCH_OCTAVE,+SSDA_CFG_NO_PITCH_BELOW_RANGE,+SSDA_CFG_NO_PITCH_PUSH"
  "every field at its largest|ok|RATE_HZ=48000,F0_MIN_HZ=10,F0_MAX_HZ=12000,FRAME_LEN=8192,HOP=65535,THRESHOLD_Q15=32767,VOICING_Q15=32767,SILENCE_MAD=65535,CHUNK=8192,LOWPASS_HZ=12000,FLAGS=0x3F")
set(_failed 0)
foreach(_case IN LISTS _cases)
  string(REPLACE "|" ";" _parts "${_case}")
  string(REPLACE "," ";" _parts "${_parts}")
  list(GET _parts 0 _name)
  list(GET _parts 1 _check)
  list(SUBLIST _parts 2 -1 _settings)
  set(_defs -DSSDA_CFG_PITCH_FIXED)
  foreach(_s IN LISTS _settings)
    if(_s MATCHES "^\\+(.*)")
      list(APPEND _defs -D${CMAKE_MATCH_1})
    else()
      list(APPEND _defs -DSSDA_CFG_PITCH_FIXED_${_s})
    endif()
  endforeach()
  execute_process(COMMAND ${CC} -std=c99 -I${ROOT}/include -I${ROOT}/lib ${_defs}
                          -c ${ROOT}/lib/pitch_config.c -o ${OUT}
                  RESULT_VARIABLE _rc ERROR_VARIABLE _err OUTPUT_VARIABLE _out)
  if(_check STREQUAL "ok")
    if(NOT _rc EQUAL 0)
      message(SEND_ERROR "${_name}: does not compile:\n${_err}")
      math(EXPR _failed "${_failed} + 1")
    endif()
  elseif(_rc EQUAL 0 OR NOT _err MATCHES "ssda__pitch_fixed_${_check}")
    message(SEND_ERROR "${_name}: expected a compile error naming ssda__pitch_fixed_${_check}:\n${_err}")
    math(EXPR _failed "${_failed} + 1")
  endif()
endforeach()
list(LENGTH _cases _n)
if(_failed GREATER 0)
  message(FATAL_ERROR "${_failed} of ${_n} cases wrong")
endif()
message(STATUS "${_n} cases: each invalid setting refused by its check, the valid one compiles")
