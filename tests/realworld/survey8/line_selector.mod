MODULE LineSelector
  ! Our own program in the style of a palletizing line (survey round 8): the I/O signals
  ! are named with their kind last (Line_Gi, Suck_Gi, Vacuum_Do), as some integrators do.
  VAR num nLine := 0;
  VAR bool bEmpty := FALSE;

  PROC main()
    nLine := Line_Gi;
    IF Suck_Gi = 0 THEN
      bEmpty := TRUE;
    ENDIF
    SetDO Vacuum_Do, 1;
  ENDPROC
ENDMODULE
