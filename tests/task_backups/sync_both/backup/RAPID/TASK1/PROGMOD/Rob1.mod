MODULE Rob1
  VAR syncident cycle_done;
  PERS tasks pair{2} := [["T_ROB1"], ["T_ROB2"]];
  PERS num cycles1 := 0;
  PERS num cycles2 := 0;
  PROC main()
    WHILE TRUE DO
      cycles1 := (cycles1 + 1) MOD 4;
      WaitSyncTask cycle_done, pair;
    ENDWHILE
  ENDPROC
ENDMODULE
