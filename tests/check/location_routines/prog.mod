MODULE LocationRoutines
    ! A GOTO loop that calls Work twice.
    VAR num n := 0;

    PROC main()
        n := 0;
        again:
        Work;
        n := n + 1;
        IF n < 2 GOTO again;
    ENDPROC

    PROC Work()
        n := n + 10;
        n := n - 10;
    ENDPROC
ENDMODULE
