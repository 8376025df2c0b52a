MODULE RuntimeArrayIndex
    ! The index is DInput + 2: 2 or 3, but the array has 2 elements.
    VAR num slots{2} := [10, 20];
    VAR num picked := 0;

    PROC main()
        WHILE TRUE DO
            picked := slots{DInput(di_slot) + 2};
        ENDWHILE
    ENDPROC
ENDMODULE
