"""Spreadsheet output of a run (simlab/timeseries.h): the CSV dialects and the .xlsx workbook,
written by the CLI (`run --csv --csv-dialect --xlsx`) and by Simulation.run(csv=, xlsx=). The
workbook is read back by an independent reader (openpyxl) and its numbers are checked against the
CSV of the same run; its charts are read from the workbook's own XML parts."""

import csv
import io
import os
import re
import subprocess
import zipfile

import openpyxl
import pytest

import elasticlab as el

CLI = os.environ.get("ELASTIC_LAB_CLI")

RUN = ["run", "--scene", "ring2d", "--duration", "0.05", "--every", "3", "--quiet"]


def cli(*args, check=True):
    if not CLI:
        pytest.fail("ELASTIC_LAB_CLI is not set (CTest sets it)")
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=check)


def plain_rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.reader(f))


def test_semicolon_dialect_is_the_plain_table_respelled(tmp_path):
    plain, semi = tmp_path / "plain.csv", tmp_path / "semi.csv"
    cli(*RUN, "--csv", str(plain))
    cli(*RUN, "--csv", str(semi), "--csv-dialect", "excel-semicolon")
    raw = semi.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf"), "a UTF-8 byte-order mark opens the file"
    body = raw[3:]
    assert body.endswith(b"\r\n") and body.count(b"\n") == body.count(b"\r\n"), "every line ends CRLF"
    assert b"." not in body, "no decimal point left"
    rows = list(csv.reader(io.StringIO(body.decode("utf-8"), newline=""), delimiter=";"))
    expected = plain_rows(plain)
    assert len(rows) == len(expected) > 3
    # The same shortest round-trip texts, only the decimal separator differs.
    assert [[cell.replace(",", ".") for cell in row] for row in rows] == expected
    # A spreadsheet in a decimal-comma locale reads "-1,25e-05" as a number: one comma at most.
    assert all(cell.count(",") <= 1 for row in rows[1:] for cell in row)


def test_unknown_dialect_is_refused_with_one_message(tmp_path):
    out = cli(*RUN, "--csv", str(tmp_path / "x.csv"), "--csv-dialect", "excel", check=False)
    assert out.returncode == 2
    message = "csv dialect 'excel' is unknown; one of plain, excel-semicolon"
    assert message in out.stderr
    assert not (tmp_path / "x.csv").exists()
    with pytest.raises(ValueError, match=re.escape(message)):
        el.Simulation("ring2d").run(0.01, csv=str(tmp_path / "y.csv"), csv_dialect="excel")


def check_workbook(xlsx, plain_csv, scene_charts):
    rows = plain_rows(plain_csv)
    header, data = rows[0], rows[1:]
    book = openpyxl.load_workbook(xlsx, read_only=True)
    assert book.sheetnames == ["run", "charts"]
    sheet = list(book["run"].iter_rows(values_only=True))
    # Units in the header: "t [s]", "energy_kinetic [J]", "volume_inner [m²]"; names as the CSV's.
    names = [str(h).split(" [")[0] for h in sheet[0]]
    assert names == header
    units = dict(zip(header, sheet[0]))
    assert units["t"] == "t [s]" and units["energy_total"] == "energy_total [J]"
    assert units["step"] == "step"
    assert len(sheet) - 1 == len(data)
    for got, want in zip(sheet[1:], data):
        for g, w in zip(got, want):
            assert isinstance(g, (int, float)), "native number cells, not text"
            # 16 significant digits in the workbook (libxlsxwriter's "%.16G"), shortest
            # round-trip texts in the CSV: equal to half a unit of the 16th digit.
            assert g == pytest.approx(float(w), rel=1e-15, abs=1e-300)
    book.close()
    # The charts: native scatter charts whose series read the "run" sheet's columns.
    with zipfile.ZipFile(xlsx) as z:
        charts = sorted(n for n in z.namelist() if re.fullmatch(r"xl/charts/chart\d+\.xml", n))
        assert len(charts) == len(scene_charts)
        last = len(data) + 1
        tcol = chr(ord("A") + header.index("t"))
        for part, columns in zip(charts, scene_charts):
            xml = z.read(part).decode()
            assert "<c:scatterChart>" in xml
            for column in columns:
                col = header.index(column)
                letter = chr(ord("A") + col) if col < 26 else "A" + chr(ord("A") + col - 26)
                assert f"run!${letter}$2:${letter}${last}" in xml, (part, column)
            assert f"run!${tcol}$2:${tcol}${last}" in xml
    return header


def test_cli_workbook_matches_the_csv_of_the_same_run(tmp_path):
    plain, xlsx = tmp_path / "run.csv", tmp_path / "run.xlsx"
    cli(*RUN, "--csv", str(plain), "--xlsx", str(xlsx))
    header = check_workbook(xlsx, plain, [
        ["energy_kinetic", "energy_spring", "energy_gravity", "energy_gas", "energy_total"],
        ["volume_inner", "volume_outer"],
        ["pressure_inner", "pressure_outer"],
    ])
    assert "volume_inner" in header


def test_spring1d_has_only_the_energy_chart(tmp_path):
    plain, xlsx = tmp_path / "s.csv", tmp_path / "s.xlsx"
    cli("run", "--scene", "spring1d", "--duration", "0.05", "--quiet", "--csv", str(plain), "--xlsx", str(xlsx))
    check_workbook(xlsx, plain, [["energy_kinetic", "energy_spring", "energy_gravity", "energy_total"]])


def test_python_writes_the_cli_files(tmp_path):
    cli_csv, py_csv, py_xlsx = tmp_path / "cli.csv", tmp_path / "py.csv", tmp_path / "py.xlsx"
    cli(*RUN, "--csv", str(cli_csv), "--csv-dialect", "excel-semicolon")
    sim = el.Simulation("ring2d")
    table = sim.run(0.05, every_steps=3, csv=str(py_csv), xlsx=str(py_xlsx), csv_dialect="excel-semicolon")
    assert py_csv.read_bytes() == cli_csv.read_bytes()
    assert table.shape[0] == len(cli_csv.read_bytes().splitlines()) - 1
    plain = tmp_path / "cli-plain.csv"
    cli(*RUN, "--csv", str(plain))
    check_workbook(py_xlsx, plain, [["energy_kinetic", "energy_total"], ["volume_inner"], ["pressure_outer"]])


def test_a_workbook_too_long_for_a_sheet_is_refused_before_the_run(tmp_path):
    xlsx = tmp_path / "long.xlsx"
    out = cli("run", "--scene", "spring1d", "--dt", "1e-6", "--duration", "2", "--xlsx", str(xlsx), check=False)
    assert out.returncode == 2
    assert "do not fit a sheet of 1048575 rows; use --every 2 or more" in out.stderr
    assert not xlsx.exists()


def test_an_unwritable_workbook_is_found_before_the_run(tmp_path):
    out = cli(*RUN, "--xlsx", str(tmp_path / "no-such-folder" / "x.xlsx"), check=False)
    assert out.returncode == 2 and "x.xlsx" in out.stderr
