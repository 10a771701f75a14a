"""A figure-wide legend under the plots that fits the figure's width: as many
columns as fit (measured with the renderer, not guessed from the labels'
lengths), as many rows as that takes. A legend laid out on one row ran off
both sides of a figure of one or two sensors, clipping itself."""


def fit_bottom_legend(fig, handles, fontsize=8, width_fraction=0.98):
    """Adds the legend at the figure's bottom centre; returns its height in inches."""
    renderer = fig.canvas.get_renderer()
    width_px = fig.get_figwidth() * fig.dpi * width_fraction
    for ncol in range(len(handles), 0, -1):
        legend = fig.legend(handles=handles, loc="lower center", ncol=ncol, fontsize=fontsize,
                            frameon=False, bbox_to_anchor=(0.5, 0.0))
        box = legend.get_window_extent(renderer)
        if box.width <= width_px or ncol == 1:
            return box.height / fig.dpi
        legend.remove()
    return 0.0
