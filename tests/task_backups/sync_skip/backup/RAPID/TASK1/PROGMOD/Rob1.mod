MODULE Rob1
  VAR syncident sync1;
  PERS tasks pair{2} := [["T_ROB1"], ["T_ROB2"]];
  PROC main()
    WaitSyncTask sync1, pair;
    TPWrite "robot 1 synchronised";
  ENDPROC
ENDMODULE
