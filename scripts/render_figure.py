"""Render one figure of the paper with ParaView (run by scripts/render_figures
through `scripts/headless pvbatch`): both layers of a bilayer result side by side,
deformed by the displacement times a magnification, coloured by the von Mises
stress, with a colour bar.

Arguments: SOLUTION.pvd OUTPUT.png MAGNIFICATION TITLE
"""
import sys
from paraview.simple import *

pvd, png, magnification, title = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]

reader = PVDReader(FileName=pvd)
reader.UpdatePipeline()
view = CreateView("RenderView")
view.ViewSize = [1200, 600]
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass

lut = GetColorTransferFunction("von_mises")
lut.ApplyPreset("Rainbow Uniform", True)
vmax = 0.0
for layer, shift in ((1, 0.0), (2, 2.6)):
    threshold = Threshold(Input=reader)
    threshold.Scalars = ["CELLS", "layer"]
    try:
        threshold.LowerThreshold = layer - 0.5
        threshold.UpperThreshold = layer + 0.5
    except AttributeError:
        threshold.ThresholdRange = [layer - 0.5, layer + 0.5]
    warp = WarpByVector(Input=threshold)
    warp.Vectors = ["POINTS", "displacement"]
    warp.ScaleFactor = magnification
    moved = Transform(Input=warp)
    moved.Transform = "Transform"
    moved.Transform.Translate = [shift, 0.0, 0.0]
    display = Show(moved, view)
    ColorBy(display, ("POINTS", "von_mises"))
    display.LookupTable = lut
    moved.UpdatePipeline()
    vmax = max(vmax, moved.PointData["von_mises"].GetRange()[1])
    label = Text(Text="layer %d" % layer)
    ldisplay = Show(label, view)
    ldisplay.WindowLocation = "Any Location"
    ldisplay.Position = [0.22 + 0.45 * (layer - 1), 0.86]
    ldisplay.Color = [0, 0, 0]
    ldisplay.FontSize = 24

lut.RescaleTransferFunction(0.0, vmax)
bar = GetScalarBar(lut, view)
bar.Title = "von Mises stress"
bar.ComponentTitle = ""
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
bar.Visibility = 1
caption = Text(Text=title)
cdisplay = Show(caption, view)
cdisplay.WindowLocation = "Upper Center"
cdisplay.Color = [0, 0, 0]
cdisplay.FontSize = 22

view.InteractionMode = "2D"
view.CameraParallelProjection = 1
view.CameraPosition = [1.3, 0, 10]
view.CameraFocalPoint = [1.3, 0, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 1.45
Render(view)
SaveScreenshot(png, view, ImageResolution=[1200, 600])
