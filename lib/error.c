/* error.c - names of the error codes. */
#include "ssda/ssda.h"

const char *ssda_strerror(int err)
{
    switch (err) {
    case SSDA_OK:           return "ok";
    case SSDA_ERR_NULL:     return "null pointer";
    case SSDA_ERR_ARG:      return "argument out of range";
    case SSDA_ERR_SIZE:     return "bad dimensions";
    case SSDA_ERR_FORMAT:   return "bad or mismatched pixel format";
    case SSDA_ERR_STRIDE:   return "bad row stride or alignment";
    case SSDA_ERR_OVERFLOW: return "result not representable";
    case SSDA_ERR_BUFFER:   return "buffer too small";
    case SSDA_ERR_IO:       return "i/o error";
    case SSDA_ERR_STATE:    return "wrong state";
    case SSDA_ERR_UNSUPPORTED: return "feature not in this build";
    default:                return err < 0 ? "error from a callback" : "unknown";
    }
}
