MODULE Rob2
  VAR syncident sync1;
  PERS tasks pair{2} := [["T_ROB1"], ["T_ROB2"]];
  PROC main()
    ! skips the synchronisation when diSkip is 1: robot 1 then waits forever
    IF diSkip = 0 THEN
      WaitSyncTask sync1, pair;
    ENDIF
    TPWrite "robot 2 done";
  ENDPROC
ENDMODULE
