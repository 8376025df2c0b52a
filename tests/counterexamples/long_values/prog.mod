MODULE LongValues
    ! Values too long for a screen: an array of 120 numbers written whole with a few of
    ! them changed, a string of 78 characters, a source line of 480 characters that
    ! is never reached. The text report shows the changed elements, shortens the string
    ! and keeps every line within 300 characters; --full-trace shows every value whole.
    VAR num table{120};
    VAR num limits{120} := [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120];
    VAR string message := "";
    VAR num divisor := 0;

    PROC main()
        table := limits;
        table{2} := 0;
        table := [1, 2, 3, 4, 7, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 7, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 7, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 7, 111, 112, 113, 114, 115, 116, 117, 118, 119, 120];
        message := "The gripper reported a fault while the part was released at station four";
        IF divisor > 0 THEN
            message := "part 1" + "part 2" + "part 3" + "part 4" + "part 5" + "part 6" + "part 7" + "part 8" + "part 9" + "part 10" + "part 11" + "part 12" + "part 13" + "part 14" + "part 15" + "part 16" + "part 17" + "part 18" + "part 19" + "part 20" + "part 21" + "part 22" + "part 23" + "part 24" + "part 25" + "part 26" + "part 27" + "part 28" + "part 29" + "part 30" + "part 31" + "part 32" + "part 33" + "part 34" + "part 35" + "part 36" + "part 37" + "part 38" + "part 39";
        ENDIF
        table{1} := table{1} / (divisor + StrLen(message) - 72);
    ENDPROC
ENDMODULE
