"""Render a bilayer result of any geometry with ParaView (run by
scripts/render_scenes through `scripts/headless pvbatch`): both layers side by
side (layer 2 shifted by 1.2 times the width of the specimen; a one-layer
result alone), deformed by
the displacement times a magnification chosen so that the largest
displacement appears as 8 % of the specimen's size, coloured by the von
Mises stress, with the cell edges, a colour bar and the title.

Arguments: SOLUTION.pvd OUTPUT.png TITLE
"""
import sys
from paraview.simple import *

pvd, png, title = sys.argv[1], sys.argv[2], sys.argv[3]

reader = PVDReader(FileName=pvd)
reader.UpdatePipeline(reader.TimestepValues[-1] if reader.TimestepValues else 0)
bounds = reader.GetDataInformation().GetBounds()
width, height = bounds[1] - bounds[0], bounds[3] - bounds[2]
size = max(width, height)
umax = max(abs(x) for x in reader.PointData["displacement"].GetRange(-1))
magnification = 0.08 * size / umax if umax > 0 else 1.0
layer_range = reader.PointData["layer"].GetRange() if "layer" in reader.PointData.keys() else (1, 2)
layers = (1, 2) if layer_range[1] > 1.5 else (1,)  # one layer: Materials/Number of layers = 1
shift = 1.2 * width if len(layers) == 2 else 0.0

view = CreateView("RenderView")
view.ViewSize = [1400, 8 * ((int(1400 * max(height, 0.3 * width) / ((1.0 + shift / width) * width)) + 200) // 8)]
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
lut = GetColorTransferFunction("von_mises")
lut.ApplyPreset("Rainbow Uniform", True)
vmax = 0.0
for layer in layers:
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
    moved.Transform.Translate = [(layer - 1) * shift, 0.0, 0.0]
    display = Show(moved, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0.3, 0.3, 0.3]
    ColorBy(display, ("POINTS", "von_mises"))
    display.LookupTable = lut
    moved.UpdatePipeline()
    vmax = max(vmax, moved.PointData["von_mises"].GetRange()[1])
lut.RescaleTransferFunction(0.0, vmax)
bar = GetScalarBar(lut, view)
bar.Title = "von Mises stress"
bar.ComponentTitle = ""
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
bar.Visibility = 1
caption = Text(Text="%s (%s; displacement x%.3g)" % (title, "layer 1 left, layer 2 right" if len(layers) == 2 else "one layer", magnification))
cdisplay = Show(caption, view)
cdisplay.WindowLocation = "Upper Center"
cdisplay.Color = [0, 0, 0]
cdisplay.FontSize = 20
view.InteractionMode = "2D"
view.CameraParallelProjection = 1
Render(view)  # the first render resets the camera; place it after that
cx = bounds[0] + 0.5 * (width + shift)
cy = bounds[2] + 0.5 * height
view.CameraPosition = [cx, cy, 10 * size]
view.CameraFocalPoint = [cx, cy, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 0.62 * max(height + 0.1 * size, (width + shift) * view.ViewSize[1] / view.ViewSize[0])
Render(view)
SaveScreenshot(png, view, ImageResolution=view.ViewSize)
