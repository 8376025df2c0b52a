MODULE Reader
  PERS bool bad := FALSE;
  PROC main()
    WHILE TRUE DO
      IF ERRNO = ERR_DIVZERO THEN
        bad := TRUE;
      ENDIF
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
