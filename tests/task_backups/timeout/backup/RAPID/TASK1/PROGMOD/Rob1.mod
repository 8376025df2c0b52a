MODULE Rob1
  VAR syncident sync1;
  PERS tasks pair{2} := [["T_ROB1"], ["T_ROB2"]];
  PERS bool timed_out := FALSE;
  PROC main()
    WaitSyncTask sync1, pair \TimeOut:=5;
    TPWrite "robot 1 synchronised";
  ERROR
    IF ERRNO = ERR_WAITSYNCTASK THEN
      timed_out := TRUE;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
