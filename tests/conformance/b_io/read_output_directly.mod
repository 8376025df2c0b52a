MODULE MainModule
  ! Tests: a signal variable used in an expression yields the signal's value (semi-value type).
  VAR signaldo doLamp;
  PROC main()
    AliasIO "DO1", doLamp;
    Set doLamp;
    IF doLamp = 1 THEN
      TPWrite "lamp on";
    ELSE
      TPWrite "lamp off";
    ENDIF
    Reset doLamp;
    IF doLamp = 1 THEN
      TPWrite "lamp on";
    ELSE
      TPWrite "lamp off";
    ENDIF
  ENDPROC
ENDMODULE
