MODULE Rob2
  VAR syncident sync1;
  PERS tasks pair{2} := [["T_ROB1"], ["T_ROB2"]];
  PROC main()
    IF diSkip = 0 THEN
      WaitSyncTask sync1, pair \TimeOut:=5;
    ENDIF
    TPWrite "robot 2 done";
  ERROR
    ! robot 1 timed out and went on: robot 2 gives up too
    RETURN;
  ENDPROC
ENDMODULE
