MODULE Link
  ! Tests: stubs for a controller link whose codes module was not given: a status starts
  ! at RC_OK, is set to RC_BUSY, and a loop retries while it is not RC_OK (a held-out
  ! network module with OK and NG). Names one datum is given and compared with are codes
  ! of different values: with both at 0 the loop would end before its first round.
  VAR num status := RC_OK;
  VAR num tries := 0;

  PROC main()
    status := RC_BUSY;
    WHILE status <> RC_OK DO
      tries := tries + 1;
      IF tries > 3 status := RC_OK;
    ENDWHILE
  ENDPROC
ENDMODULE
