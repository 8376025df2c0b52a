MODULE MainModule
  ! Tests: with no labelled key, \MaxTime ends the dialog: ERR_TP_MAXTIME to the handler.
  PROC main()
    VAR num key := 7;
    TPReadFK key, "Door open", stEmpty, stEmpty, stEmpty, stEmpty, stEmpty \MaxTime:=3;
    TPWrite "no timeout";
  ERROR
    IF ERRNO = ERR_TP_MAXTIME THEN
      TPWrite "timed out, key " \Num:=key;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
