#!/usr/bin/env python3
"""Check an XDMF sidecar of xcable (&output xdmf) against its HDF5 file.

    tools/check_xdmf.py results/case.xmf [--vtk]

Without --vtk it reads the sidecar as XML and resolves every item by itself
(h5py): one grid per snapshot, at the snapshot's time; the points of grid i
are row i of /x, /y (or zeros) and /z; every other snapshot field is an
attribute of the nodes, row i; the cells are the segments between
neighbouring output nodes, except across a break (where the output repeats
the arc length of the cut). With --vtk it reads the pair through VTK's XDMF
reader (vtkXdmfReader, the reader ParaView opens .xmf files with; PyPI vtk)
and compares every point and attribute with h5py's values; an error the
reader reports (ParaView would show it) fails the check too. Exit 0 when all
agree exactly, 1 otherwise, with the first difference on stderr.
"""
import sys
import os
import xml.etree.ElementTree as ET

import h5py
import numpy as np

GEOMETRY = ('x', 'y', 'z')


def fail(message):
    print('check_xdmf: ' + message, file=sys.stderr)
    sys.exit(1)


def expected_segments(s):
    """Segments between neighbours, none across a break (a repeated arc length)."""
    return [(k, k + 1) for k in range(len(s) - 1) if s[k + 1] != s[k]]


def hyperslab(item, h5, folder):
    """Values of a HyperSlab DataItem: (dataset name, row)."""
    children = item.findall('DataItem')
    if len(children) != 2:
        fail('a HyperSlab item must have a selection and a dataset')
    sel = np.array(children[0].text.split(), dtype=int).reshape(3, 2)
    file_name, _, name = children[1].text.strip().partition(':')
    if os.path.join(folder, file_name) != h5.filename and file_name != os.path.basename(h5.filename):
        fail('a hyperslab reads another file: ' + file_name)
    data = h5[name]
    dims = tuple(int(d) for d in children[1].get('Dimensions').split())
    if dims != data.shape:
        fail('%s: Dimensions %s, the dataset has %s' % (name, dims, data.shape))
    if list(sel[1]) != [1, 1] or sel[2][0] != 1 or sel[2][1] != data.shape[1] or sel[0][1] != 0:
        fail('%s: the selection %s is not one whole row' % (name, sel.tolist()))
    return name.lstrip('/'), int(sel[0][0]), data[sel[0][0], :]


def check_xml(xmf, h5):
    folder = os.path.dirname(os.path.abspath(xmf))
    root = ET.parse(xmf).getroot()
    domain = root.find('Domain')
    topology = domain.find('Topology')
    cells = np.array(topology.find('DataItem').text.split(), dtype=int).reshape(-1, 2)
    if int(topology.get('NumberOfElements')) != len(cells):
        fail('NumberOfElements %s, %d segments listed' % (topology.get('NumberOfElements'), len(cells)))
    want = expected_segments(h5['s'][:])
    if [tuple(c) for c in cells] != want:
        fail('the segments are not the pairs of neighbours within each piece')
    time = h5['time'][:]
    grids = domain.find('Grid').findall('Grid')
    if len(grids) != len(time):
        fail('%d grids for %d snapshots' % (len(grids), len(time)))
    fields = sorted(k for k in h5.keys()
                    if isinstance(h5[k], h5py.Dataset) and h5[k].ndim == 2 and k not in GEOMETRY)
    for i, grid in enumerate(grids):
        if float(grid.find('Time').get('Value')) != time[i]:
            fail('grid %d: time %s, /time has %r' % (i, grid.find('Time').get('Value'), time[i]))
        geometry = grid.find('Geometry').findall('DataItem')
        if len(geometry) != 3:
            fail('grid %d: geometry of %d items' % (i, len(geometry)))
        for axis, item in zip(GEOMETRY, geometry):
            if item.get('ItemType') == 'HyperSlab':
                name, row, _ = hyperslab(item, h5, folder)
                if (name, row) != (axis, i):
                    fail('grid %d: %s reads row %d of /%s' % (i, axis, row, name))
            elif axis == 'y' and 'y' not in h5:
                if item.get('Reference') != 'XML':
                    fail('grid %d: y of a planar run is not the zeros' % i)
            else:
                fail('grid %d: %s is not read from the file' % (i, axis))
        names = []
        for attribute in grid.findall('Attribute'):
            name, row, _ = hyperslab(attribute.find('DataItem'), h5, folder)
            if name != attribute.get('Name') or row != i or attribute.get('Center') != 'Node':
                fail('grid %d: attribute %s reads row %d of /%s' % (i, attribute.get('Name'), row, name))
            names.append(name)
        if sorted(names) != fields:
            fail('grid %d: attributes %s, the file has %s' % (i, sorted(names), fields))
    return len(grids), len(cells), len(fields)


def check_vtk(xmf, h5):
    from vtkmodules.vtkIOXdmf2 import vtkXdmfReader
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXdmfReader()
    errors = []
    reader.AddObserver('ErrorEvent', lambda obj, event: errors.append(event))
    reader.SetFileName(xmf)
    reader.UpdateInformation()
    times = reader.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    time = h5['time'][:]
    if times is None or not np.array_equal(np.array(times), time):
        fail('VTK reads other times than /time')
    fields = [k for k in h5.keys() if isinstance(h5[k], h5py.Dataset) and h5[k].ndim == 2 and k not in GEOMETRY]
    for i, t in enumerate(time):
        reader.UpdateTimeStep(t)
        grid = reader.GetOutputDataObject(0)
        points = vtk_to_numpy(grid.GetPoints().GetData())
        y = h5['y'][i] if 'y' in h5 else np.zeros_like(h5['x'][i])
        if not np.array_equal(points, np.stack([h5['x'][i], y, h5['z'][i]], 1)):
            fail('VTK: the points of snapshot %d differ from the file' % i)
        for name in fields:
            array = grid.GetPointData().GetArray(name)
            if array is None or not np.array_equal(vtk_to_numpy(array), h5[name][i]):
                fail('VTK: %s of snapshot %d differs from the file' % (name, i))
        cells = [tuple(grid.GetCell(c).GetPointIds().GetId(j) for j in range(2))
                 for c in range(grid.GetNumberOfCells())]
        if cells != expected_segments(h5['s'][:]):
            fail('VTK: the cells of snapshot %d are not the segments of the pieces' % i)
    if errors:
        fail('VTK reported %d errors reading the pair (a ParaView user sees them)' % len(errors))


def main():
    if len(sys.argv) < 2:
        fail('usage: check_xdmf.py <sidecar.xmf> [--vtk]')
    xmf = sys.argv[1]
    root = ET.parse(xmf).getroot()
    item = root.find('.//DataItem[@Format="HDF"]')
    h5_name = item.text.strip().partition(':')[0]
    with h5py.File(os.path.join(os.path.dirname(os.path.abspath(xmf)), h5_name), 'r') as h5:
        grids, cells, fields = check_xml(xmf, h5)
        reader = 'the XML resolved with h5py'
        if '--vtk' in sys.argv[2:]:
            check_vtk(xmf, h5)
            reader += " and VTK's XDMF reader"
    print('check_xdmf: %s: %d snapshots, %d segments, %d fields: %s agree with the file'
          % (xmf, grids, cells, fields, reader))


if __name__ == '__main__':
    main()
