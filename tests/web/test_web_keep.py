"""Keep, annotate, share on the run page and the jobs list in a real browser (headless
Chromium, Selenium) against `slipfront serve` on loopback (docs/web.md): the tags and the note
edited on the run page are what the server then holds; a bad tag is refused beside the
buttons naming its field; archive hides the run from the jobs list until "show archived" is
ticked; restore lists it again; delete asks first and then removes the run.

    /usr/bin/python3 tests/web/test_web_keep.py --binary build/slipfront --web-dir build/share/slipfront/web
"""

import os
import time

from browser_harness import CONFIG, BrowserCase, run

TINY = {"geometry": {"nodes_per_meter": 5}, "time": {"duration": 2.0}}


class WebKeep(BrowserCase):
    @classmethod
    def setUpClass(cls):
        cls.start(workers=1)

    def run_job(self, name):
        r = self.server.submit({**TINY, "name": name, "tags": ["draft"]})
        self.assertEqual(r.status_code, 201, r.text)
        return self.server.wait_status(r.json()["id"], {"succeeded"}, timeout=60)

    def job(self, job_id):
        return self.server.get(f"/api/v1/jobs/{job_id}").json()

    def open_job(self, job_id):
        self.open(f"/#/jobs/{job_id}")
        self.wait(lambda d: self.css("#keep-save"), message="the Keep card")

    def shot_card(self, selector, name):
        if not CONFIG["shots"]:
            return
        os.makedirs(CONFIG["shots"], exist_ok=True)
        self.js("arguments[0].scrollIntoView({block: 'start'})", self.css(selector)[0])
        time.sleep(0.3)
        self.css(selector)[0].screenshot(os.path.join(CONFIG["shots"], f"{name}.png"))

    def listed_ids(self):
        return self.js("return [...document.querySelectorAll('#jobs-table tbody tr[data-id]')]"
                       ".map(r => r.dataset.id)")

    def test_edit_tags_and_note_on_the_run_page(self):
        job = self.run_job("web keep")
        self.open_job(job["id"])
        self.assertEqual(self.css("#keep-tags")[0].get_attribute("value"), "draft")
        tags, note = self.css("#keep-tags")[0], self.css("#keep-note")[0]
        tags.clear()
        tags.send_keys("fig-2, keep")
        note.send_keys("the run of Fig. 2\nmesh checked")
        self.css("#keep-save")[0].click()
        self.wait(lambda d: self.job(job["id"])["tags"] == ["fig-2", "keep"], message="saved tags")
        self.assertEqual(self.job(job["id"])["note"], "the run of Fig. 2\nmesh checked")
        self.wait(lambda d: self.css("#keep-message")[0].text == "saved", message="'saved'")
        # The provenance card shows the new tags too.
        self.wait(lambda d: any("fig-2, keep" in t for t in self.texts(".kv td")),
                  message="the new tags in the provenance card")
        self.shot_card("#job-keep", "web-job-keep")  # docs/figures/web-job-keep.png
        # A tag longer than 64 bytes: refused beside the buttons, nothing changed.
        tags = self.css("#keep-tags")[0]
        tags.clear()
        tags.send_keys("x" * 65)
        self.css("#keep-save")[0].click()
        self.wait(lambda d: "/tags_add/0" in self.css("#keep-message")[0].text,
                  message="the refusal")
        self.assertEqual(self.job(job["id"])["tags"], ["fig-2", "keep"])
        self.assert_no_console_errors("the run page", expected=("422",))
        self.shot("job-keep")

    def test_a_tag_added_elsewhere_meanwhile_stays(self):
        """The page sends the tags added and removed, not the whole list: a tag another
        client added while the page was open is kept when the page saves."""
        job = self.run_job("web tags meanwhile")
        self.open_job(job["id"])
        r = self.server.session.patch(self.server.url(f"/api/v1/jobs/{job['id']}"),
                                      json={"tags_add": ["from-cli"]}, timeout=10)
        self.assertEqual(r.status_code, 200, r.text)
        tags = self.css("#keep-tags")[0]
        tags.clear()
        tags.send_keys("fig-3")  # "draft" removed, "fig-3" added
        self.css("#keep-save")[0].click()
        self.wait(lambda d: self.job(job["id"])["tags"] == ["from-cli", "fig-3"],
                  message="draft removed, fig-3 added, from-cli kept")
        self.assert_no_console_errors("the run page")

    def test_a_cache_hit_shows_the_original_runs_wall_time_marked_cached(self):
        first = self.run_job("web original")
        r = self.server.submit({**TINY, "name": "web reused", "tags": ["draft"]})
        self.assertEqual((r.status_code, r.json()["cache"]), (201, "hit"), r.text)
        hit = r.json()
        self.open("/#/jobs")
        self.wait(lambda d: hit["id"] in self.listed_ids(), message="the jobs list")
        row = lambda i: self.css(f"#jobs-table tr[data-id='{i}']")[0].text  # noqa: E731
        self.assertIn("cached", row(hit["id"]))
        if not first.get("cached_from"):  # the original ran here: its own time, not "cached"
            self.assertNotIn("cached", row(first["id"]))
        self.assertIsNotNone(self.job(hit["id"])["metrics"]["wall_time_s"])
        self.assert_no_console_errors("the jobs list")

    def test_archive_restore_and_delete(self):
        job = self.run_job("web archive")
        visible = self.run_job("web listed")
        self.open_job(job["id"])
        self.css("#keep-archive")[0].click()
        self.wait(lambda d: self.css("#keep-archived"), message="archived")
        self.assertIsNotNone(self.job(job["id"])["archived_at"])
        self.open("/#/jobs")
        self.wait(lambda d: visible["id"] in self.listed_ids(), message="the jobs list")
        self.assertNotIn(job["id"], self.listed_ids())
        self.css("#job-archived")[0].click()
        self.wait(lambda d: job["id"] in self.listed_ids(), message="archived runs shown")
        row = self.css(f"#jobs-table tr[data-id='{job['id']}']")[0]
        self.assertIn("archived", row.text)
        self.open_job(job["id"])
        self.css("#keep-archive")[0].click()  # Restore
        self.wait(lambda d: self.job(job["id"])["archived_at"] is None, message="restored")
        # Delete: dismissed first, then accepted.
        self.wait(lambda d: self.css("#keep-delete"), message="the delete button")
        self.css("#keep-delete")[0].click()
        self.driver.switch_to.alert.dismiss()
        self.assertEqual(self.server.get(f"/api/v1/jobs/{job['id']}").status_code, 200)
        self.css("#keep-delete")[0].click()
        self.driver.switch_to.alert.accept()
        self.wait(lambda d: self.server.get(f"/api/v1/jobs/{job['id']}").status_code == 404,
                  message="deleted")
        self.wait(lambda d: d.current_url.endswith("#/jobs"), message="back to the jobs")
        self.assert_no_console_errors("archive and delete")

    def test_a_study_kept_on_its_page(self):
        """The study page's Keep card: tags and note saved, archive hides the study from the
        studies list until "show archived", delete (after a confirmation) removes the study
        with its runs."""
        body = {"name": "web kept study", "tags": ["draft"], "grid": {"L": [6.9e-4], "n_d": [5]},
                "base": {"geometry": {"width": 12, "x_min": -1, "height": 4},
                         "probe": {"arrival_x1": 3, "spectrum_x1": 2}, "time": {"duration": 3}}}
        r = self.server.post("/api/v1/studies", json=body)
        self.assertEqual(r.status_code, 201, r.text)
        study_id = r.json()["id"]
        study = lambda: self.server.get(f"/api/v1/studies/{study_id}").json()  # noqa: E731
        self.wait(lambda d: study()["status"] == "finished", timeout=120, message="finished")
        job_id = study()["runs"][0]["job_id"]
        self.open(f"/#/studies/{study_id}")
        self.wait(lambda d: self.css("#study-keep #keep-save"), message="the study's Keep card")
        self.assertEqual(self.css("#keep-tags")[0].get_attribute("value"), "draft")
        tags, note = self.css("#keep-tags")[0], self.css("#keep-note")[0]
        tags.clear()
        tags.send_keys("fig-3, kammer2014")
        note.send_keys("the L sweep of Fig. 3")
        self.css("#keep-save")[0].click()
        self.wait(lambda d: study()["tags"] == ["fig-3", "kammer2014"], message="saved tags")
        self.assertEqual(study()["note"], "the L sweep of Fig. 3")
        # Export: the archive of the study with its run, of the size the API's export has
        # (its members are the same; only the export time inside differs, in the same width).
        self.css("#study-export")[0].click()
        self.wait(lambda d: self.css("#study-export-link"), message="the archive")
        link = self.css("#study-export-link")[0]
        self.assertEqual(link.get_attribute("download"), f"slipfront-study-{study_id}.tar")
        r = self.server.get(f"/api/v1/studies/{study_id}/export", timeout=60)
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.assertIn(b'"study": "study.json"', r.content)
        self.assertEqual(link.text, f"slipfront-study-{study_id}.tar ({len(r.content)} bytes)")
        self.shot_card("#study-keep", "web-study-keep")
        self.css("#keep-archive")[0].click()
        self.wait(lambda d: self.css("#keep-archived"), message="archived")
        self.assertIsNotNone(study()["archived_at"])
        self.open("/#/studies")
        rows = lambda: self.js("return [...document.querySelectorAll('#studies-table tbody tr[data-id]')]"  # noqa: E731
                               ".map(r => r.dataset.id)")
        self.wait(lambda d: self.css("#studies-table tbody tr"), message="the studies list")
        self.assertNotIn(study_id, rows())
        self.css("#study-archived")[0].click()
        self.wait(lambda d: study_id in rows(), message="archived studies shown")
        self.assertIn("archived", self.css(f"#studies-table tr[data-id='{study_id}']")[0].text)
        self.open(f"/#/studies/{study_id}")
        self.wait(lambda d: self.css("#study-keep #keep-delete"), message="the delete button")
        self.css("#keep-delete")[0].click()
        self.driver.switch_to.alert.dismiss()
        self.assertEqual(self.server.get(f"/api/v1/studies/{study_id}").status_code, 200)
        self.css("#keep-delete")[0].click()
        self.driver.switch_to.alert.accept()
        self.wait(lambda d: self.server.get(f"/api/v1/studies/{study_id}").status_code == 404,
                  message="deleted")
        self.assertEqual(self.server.get(f"/api/v1/jobs/{job_id}").status_code, 404)
        self.wait(lambda d: d.current_url.endswith("#/studies"), message="back to the studies")
        self.assert_no_console_errors("the study page")
        self.shot("study-keep")


if __name__ == "__main__":
    run()
