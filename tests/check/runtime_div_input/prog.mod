MODULE RuntimeDivInput
    ! Divides by the value of a free digital input: it may be 0.
    VAR num ratio := 0;

    PROC main()
        WHILE TRUE DO
            ratio := 10 / DInput(di_count);
        ENDWHILE
    ENDPROC
ENDMODULE
