MODULE Reader
  PERS bool bad := FALSE;
  PROC main()
    WHILE TRUE DO
      IF INTNO <> 0 THEN
        bad := TRUE;
      ENDIF
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
