MODULE TpAnswers
    ! Reads a count on the FlexPendant and divides by count - 2.
    VAR num count := 0;
    VAR num share := 0;

    PROC main()
        TPReadNum count, "How many parts?";
        share := 12 / (count - 2);
    ENDPROC
ENDMODULE
