MODULE B
  PERS tasks both{2};
  VAR syncident s1;
  PERS bool timedOut;
  PERS num n := 0;
  PROC main()
    WaitSyncTask s1, both;
    n := 1;
  ENDPROC
ENDMODULE
