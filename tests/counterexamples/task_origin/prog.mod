MODULE Main
    ! The main task divides by a count the other task clears: the headline says which
    ! task set it, not that it came from an input.
    PERS num parts := 1;
    VAR num share := 0;

    PROC main()
        WaitUntil parts = 0;
        share := 10 / parts;
    ENDPROC
ENDMODULE
