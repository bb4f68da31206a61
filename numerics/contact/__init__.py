"""The numerical contact of two tori: boundary elements on the exact gap (:mod:`.bem`), the contact at any
angle and its power law (:mod:`.angle`), and the contact whose pressure is capped by yield (:mod:`.plastic`)."""
