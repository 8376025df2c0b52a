MODULE EndSequence
    ! Three assignments, then the end of main.
    VAR num x := 0;

    PROC main()
        x := 1;
        x := 2;
        x := 3;
    ENDPROC
ENDMODULE
