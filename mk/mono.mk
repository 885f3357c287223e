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
