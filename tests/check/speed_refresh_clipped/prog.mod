MODULE prog
  ! The manual's pattern: an override out of range is clipped in the ERROR handler and the
  ! SpeedRefresh retried. The handler's lines run (override 101 -> 100).
  VAR signalgi gi_override;
  VAR num override := 100;
  PROC main()
    AliasIO "GI_OVERRIDE", gi_override;
    override := GInput(gi_override);
    SpeedRefresh override;
  ERROR
    IF ERRNO = ERR_SPEED_REFRESH_LIM THEN
      IF override > 100 override := 100;
      IF override < 0 override := 0;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
