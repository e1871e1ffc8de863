/* my_ssda_config.h - a user's settings file, outside include/ (test
   config_file: the library built with -DSSDA_CONFIG_FILE=my_ssda_config.h). */
#define SSDA_CFG_NO_RAMP
