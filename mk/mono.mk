# mk/mono.mk: the monochrome panels in `make demo`: the demo scene on an
# emulated SSD1306 (filled with ordered dithering, and as a hidden-line
# drawing) and on an emulated SSD1680 e-paper.
DEMO_TARGETS += demo-mono

.PHONY: demo-mono
demo-mono: $(SIM) | deps
	@mkdir -p $(OUT)
	$(SIM) panel --panel ssd1306-128x64 --out $(OUT)/mono_ssd1306.png \
	    --lines-out $(OUT)/lines_ssd1306.png
	$(SIM) panel --panel ssd1680-122x250 --diffuse --out $(OUT)/mono_ssd1680.png \
	    --lines-out $(OUT)/lines_ssd1680.png

# The vector hidden lines of app/zs_hlines.c against a ray caster.
HLINES_TEST := $(BUILD)/tests/app/test_hlines
TEST_SUITES += $(HLINES_TEST)

$(HLINES_TEST): tests/app/test_hlines.c app/zs_hlines.c app/zs_hlines.h | deps
	@mkdir -p $(@D) $(OUT)
	$(CC) $(TEST_CFLAGS) -D_POSIX_C_SOURCE=200809L -Iapp -o $@ tests/app/test_hlines.c \
	    app/zs_hlines.c $(TEST_LIBS)
