MODULE InputDivision
    ! The operator's answer divides: an answer of 1 makes the divisor 0.
    VAR num parts := 0;
    VAR num per_part := 0;
    VAR num batch := 12;

    PROC main()
        TPReadNum parts, "How many parts?";
        per_part := batch / (parts - 1);
    ENDPROC
ENDMODULE
