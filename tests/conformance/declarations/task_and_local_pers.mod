MODULE task_and_local_pers
  ! Tests: TASK PERS and LOCAL PERS / LOCAL VAR declarations are read and
  ! written like ordinary persistents and variables within their module.
  TASK PERS num tp := 1;
  LOCAL PERS string lp := "x";
  LOCAL VAR num lv := 2;
  PROC main()
    tp := tp + lv;
    lp := lp + "y";
    TPWrite lp \Num:=tp;
  ENDPROC
ENDMODULE
