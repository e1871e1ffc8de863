/*
 * fw_base.c - the empty firmware: startup code and a main that returns.
 * Every feature image is this plus -Wl,--undefined=<each public function of
 * the feature's header>, so the linker keeps that API and all it calls;
 * the feature's flash and RAM are the difference in section sizes.
 */
int main(void);

int main(void)
{
    return 0;
}
